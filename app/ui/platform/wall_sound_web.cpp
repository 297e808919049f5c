// The browser's wall clicks: Web Audio. The AudioContext is made when sound is turned on, which
// follows a key press or a click; should the page have had no gesture yet (sound turned on by
// swarmlab.set() from a script), it starts suspended and resumes at the next one.

#include <emscripten.h>

#include "i18n/translator.h"
#include "ui/platform/wall_sound.h"

namespace {

// 1: a context exists (running or waiting for a gesture); 0: this browser has no Web Audio.
EM_JS(int, web_audio_open, (), {
  try {
    var Context = window.AudioContext || window.webkitAudioContext;
    if (!Context) return 0;
    if (!Module.swarmlabAudio) {
      var ctx = new Context();
      Module.swarmlabAudio = ctx;
      // One click: a 2.5 kHz tone dying away in about 3 ms, like a Geiger counter's.
      var n = Math.round(ctx.sampleRate * 0.006);
      var click = ctx.createBuffer(1, n, ctx.sampleRate);
      var data = click.getChannelData(0);
      for (var k = 0; k < n; ++k) {
        var t = k / ctx.sampleRate;
        data[k] = 0.5 * Math.exp(-t / 0.0012) * Math.sin(2 * Math.PI * 2500 * t);
      }
      Module.swarmlabClick = click;
      var resume = function() {
        if (Module.swarmlabAudio && Module.swarmlabAudio.state === 'suspended')
          Module.swarmlabAudio.resume();
      };
      window.addEventListener('pointerdown', resume, true);
      window.addEventListener('keydown', resume, true);
    }
    if (Module.swarmlabAudio.state === 'suspended') Module.swarmlabAudio.resume();
    return 1;
  } catch (e) {
    return 0;
  }
});

EM_JS(void, web_audio_suspend, (), {
  if (Module.swarmlabAudio) Module.swarmlabAudio.suspend();
});

// 1 when the clicks were scheduled; 0 while the context waits for a gesture.
EM_JS(int, web_audio_clicks, (int clicks, double seconds), {
  var ctx = Module.swarmlabAudio;
  if (!ctx || ctx.state !== 'running') return 0;
  var start = ctx.currentTime + 0.01;
  for (var i = 0; i < clicks; ++i) {
    var source = ctx.createBufferSource();
    source.buffer = Module.swarmlabClick;
    source.connect(ctx.destination);
    source.start(start + i * seconds / clicks);
  }
  Module.swarmlabClicksPlayed = (Module.swarmlabClicksPlayed || 0) + clicks;
  return 1;
});

}  // namespace

namespace swarmlab {

std::string WallSound::open() {
  if (open_) return {};
  if (!web_audio_open()) return tr("no sound: this browser has no Web Audio");
  open_ = true;
  return {};
}

void WallSound::close() {
  if (!open_) return;
  web_audio_suspend();
  open_ = false;
}

bool WallSound::play(int clicks, double seconds) {
  return open_ && clicks > 0 && seconds > 0 && web_audio_clicks(clicks, seconds) != 0;
}

}  // namespace swarmlab
