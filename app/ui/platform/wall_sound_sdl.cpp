// The desktop's wall clicks: SDL audio, mono float samples queued a frame at a time.

#include <SDL.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "i18n/translator.h"
#include "ui/platform/wall_sound.h"

namespace swarmlab {
namespace {

constexpr int kSampleRate = 44100;
/// More than this much queued (seconds) and the frame's clicks are dropped: clicks heard late
/// would no longer go with the wall hits seen.
constexpr double kMostQueued = 0.15;

/// One click: a 2.5 kHz tone dying away in about 3 ms, like a Geiger counter's.
void add_click(std::vector<float>& out, std::size_t at) {
  constexpr double kPi = 3.14159265358979323846;
  for (std::size_t k = 0; k < 240 && at + k < out.size(); ++k) {
    const double t = double(k) / kSampleRate;
    out[at + k] += float(0.5 * std::exp(-t / 0.0012) * std::sin(2 * kPi * 2500 * t));
  }
}

}  // namespace

std::string WallSound::open() {
  if (open_) return {};
  char error[600];
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
    std::snprintf(error, sizeof error, tr("no sound: cannot start audio (%s)"), SDL_GetError());
    return error;
  }
  SDL_AudioSpec want{}, have{};
  want.freq = kSampleRate;
  want.format = AUDIO_F32SYS;
  want.channels = 1;
  want.samples = 512;
  const SDL_AudioDeviceID device = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
  if (device == 0) {
    std::snprintf(error, sizeof error, tr("no sound: no audio device (%s)"), SDL_GetError());
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return error;
  }
  device_ = device;
  open_ = true;
  SDL_PauseAudioDevice(device, 0);
  return {};
}

void WallSound::close() {
  if (!open_) return;
  SDL_CloseAudioDevice(device_);
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
  open_ = false;
  device_ = 0;
}

bool WallSound::play(int clicks, double seconds) {
  if (!open_ || clicks <= 0 || !(seconds > 0)) return false;
  const double queued = double(SDL_GetQueuedAudioSize(device_)) / (sizeof(float) * kSampleRate);
  if (queued > kMostQueued) return false;
  std::vector<float> samples(std::size_t(std::ceil(seconds * kSampleRate)), 0.0f);
  for (int i = 0; i < clicks; ++i)
    add_click(samples, std::size_t(double(i) / clicks * double(samples.size())));
  return SDL_QueueAudio(device_, samples.data(), Uint32(samples.size() * sizeof(float))) == 0;
}

}  // namespace swarmlab
