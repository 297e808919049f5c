// Share links: a preset carried in the URL fragment, linked into swarmlab.js with --post-js
// (before swarmlab_api.js, which uses it). Two forms, both accepted when a page opens:
//   #preset=<base64url of the preset's UTF-8 JSON>            always written and read
//   #z=<base64url of the JSON compressed with deflate-raw>     shorter; needs CompressionStream
// and a lesson (docs/lessons.md) as #lesson=<a shipped lesson's id, or base64url of its JSON>
// (what the lesson panel's Share button writes; the app itself reads it, app/lessons/
// lesson_link.h) or #lz=<deflate-raw, base64url>.
// base64url is RFC 4648 section 5 without padding; padding and the '+' '/' of plain base64 are
// accepted too, as is whitespace a mail program may have inserted. The fragment never reaches
// the web server, so a link works from any static host.
// A preset is at most maxPresetBytes of UTF-8 (4 MB). A #preset= link is measured before it is
// decoded; a #z= link is inflated in small slices and stopped as soon as it passes the limit,
// so a deflate bomb costs a few milliseconds, not the tab.
var SwarmlabLink = (function () {
  'use strict';

  var utf8 = new TextEncoder();
  var strictUtf8 = new TextDecoder('utf-8', { fatal: true });
  var maxPresetBytes = 4000000;
  // Deflate expands at most about 1032:1, so a 1 KiB slice yields about 1 MB at most: the
  // inflater never runs long between two checks of the size.
  var inflateSlice = 1024;

  // The page's language (web/page_text.js); a page without it shows the English.
  var pageText = typeof window !== 'undefined' && window.pageText || englishText;
  function englishText(text) {
    var values = Array.prototype.slice.call(arguments, 1);
    return text.replace(/%[-+ #0-9.]*[sdf%]/g, function (c) { return c === '%%' ? '%' : String(values.shift()); });
  }
  /// A refusal: { error } in English (what the JS API returns) and { shown } in the page's
  /// language, from `say`, which writes its sentence with the pageText it is given.
  function refusal(say) { return { error: say(englishText), shown: say(pageText) }; }

  /// "5.2 MB" for a count of bytes.
  function sizeText(bytes) { return (bytes / 1e6).toFixed(1).replace(/\.0$/, '') + ' MB'; }

  /// The refusal of a preset of `bytes` bytes over the limit, { error, shown }; `what` names
  /// where it came from.
  function tooLarge(what, bytes) {
    return refusal(function (pageText) {
      return pageText('%s is %s; a preset may be at most %s', what, sizeText(bytes), sizeText(maxPresetBytes));
    });
  }

  function toBase64url(bytes) {
    var binary = '';
    for (var i = 0; i < bytes.length; i += 0x8000)
      binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }

  function fromBase64url(text) { // throws on anything that is not base64(url)
    var b64 = text.replace(/\s+/g, '').replace(/-/g, '+').replace(/_/g, '/').replace(/=+$/, '');
    if (!b64 || /[^A-Za-z0-9+\/]/.test(b64) || b64.length % 4 === 1) throw new Error('not base64url');
    while (b64.length % 4) b64 += '=';
    var binary = atob(b64), bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }

  function canCompress() {
    try {
      new CompressionStream('deflate-raw');
      new DecompressionStream('deflate-raw');
      return true;
    } catch (e) {
      return false;
    }
  }

  /// Inflates deflate-raw bytes, feeding the stream one slice at a time and counting what comes
  /// out. Promise<Uint8Array>; rejects with { tooLarge: true } once more than limit bytes came
  /// out, or with the stream's error.
  function inflateLimited(bytes, limit) {
    var stream = new DecompressionStream('deflate-raw');
    var writer = stream.writable.getWriter(), reader = stream.readable.getReader();
    var chunks = [], total = 0, stopped = false;
    function pump() {
      return reader.read().then(function (r) {
        if (r.done) return;
        total += r.value.length;
        if (total > limit) {
          stopped = true;
          reader.cancel().catch(function () {});
          writer.abort().catch(function () {});
          throw { tooLarge: true };
        }
        chunks.push(r.value);
        return pump();
      });
    }
    function feed(offset) {
      if (stopped) return Promise.resolve();
      if (offset >= bytes.length) return writer.close();
      return writer.write(bytes.subarray(offset, offset + inflateSlice)).then(function () {
        return feed(offset + inflateSlice);
      });
    }
    var reading = pump();
    // A write fails once the reader has stopped; the reader's verdict is the one that counts.
    var writing = feed(0).catch(function (e) { if (!stopped) throw e; });
    return Promise.all([reading, writing]).then(function () {
      var out = new Uint8Array(total), at = 0;
      for (var i = 0; i < chunks.length; ++i) { out.set(chunks[i], at); at += chunks[i].length; }
      return out;
    });
  }

  function transform(bytes, stream) { // Promise<Uint8Array>
    return new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer()
      .then(function (buffer) { return new Uint8Array(buffer); });
  }

  /// The fragment for a preset's JSON text: '#z=...' when the browser compresses and that is
  /// shorter, else '#preset=...'. Promise<string>.
  function fragment(json) {
    var bytes = utf8.encode(json);
    var plain = '#preset=' + toBase64url(bytes);
    if (!canCompress()) return Promise.resolve(plain);
    return transform(bytes, new CompressionStream('deflate-raw')).then(function (z) {
      var short = '#z=' + toBase64url(z);
      return short.length < plain.length ? short : plain;
    }, function () { return plain; });
  }

  /// The preset in a fragment ('#preset=...', '#z=...', possibly among other key=value pairs
  /// separated by '&'): null when there is none, else a Promise that always resolves, to
  /// { json } or to { error, shown } (the message in English, as the JS API returns it, and in
  /// the page's language: "share link: ...").
  function read(hash) {
    var parts = String(hash || '').replace(/^#/, '').split('&');
    for (var i = 0; i < parts.length; ++i) {
      var eq = parts[i].indexOf('=');
      if (eq < 0) continue;
      var key = parts[i].slice(0, eq), value = parts[i].slice(eq + 1);
      if (key !== 'preset' && key !== 'z' && key !== 'lesson' && key !== 'lz') continue;
      try { value = decodeURIComponent(value); } catch (e) { /* keep it as it is */ }
      // A lesson: #lesson= is read by the app, which knows the shipped lessons' ids
      // ({ lessonLink }); #lz= (deflate-raw) is inflated here ({ json, lesson: true }).
      if (key === 'lesson') {
        if (value.length > Math.ceil(maxPresetBytes / 3) * 4)
          return Promise.resolve(refusal(function (pageText) {
            return pageText('lesson link: the text after #lesson= is %s; a lesson may be at most %s',
                            sizeText(value.length * 3 / 4), sizeText(maxPresetBytes));
          }));
        return Promise.resolve({ lessonLink: value });
      }
      if (key === 'lz')
        return decode(key, value).then(function (r) { r.lesson = true; return r; });
      return decode(key, value);
    }
    return null;
  }

  function decode(key, value) {
    // base64url carries 3 bytes in 4 characters; a deflated preset is never much longer than
    // the preset, so either form over the limit is refused before it is decoded.
    var characters = value.replace(/\s+/g, '').length;
    if (characters > Math.ceil(maxPresetBytes / 3) * 4)
      return Promise.resolve(tooLarge('share link: the preset in #' + key + '=', Math.floor(characters * 3 / 4)));
    var bytes;
    try {
      bytes = fromBase64url(value);
    } catch (e) {
      return Promise.resolve(refusal(function (pageText) {
        return pageText('share link: the text after #%s= is not base64url (the link may have been cut short)', key);
      }));
    }
    var inflated = key === 'preset' || key === 'lesson' ? Promise.resolve(bytes)
      : !canCompress() ? null
      : inflateLimited(bytes, maxPresetBytes);
    if (!inflated)
      return Promise.resolve(refusal(function (pageText) {
        return pageText('share link: the text after #%s= needs a browser that can decompress (DecompressionStream); a #preset= link works everywhere', key);
      }));
    return inflated.then(function (raw) {
      try {
        return { json: strictUtf8.decode(raw) };
      } catch (e) {
        return refusal(function (pageText) {
          return pageText('share link: the text after #%s= is not UTF-8 text', key);
        });
      }
    }, function (e) {
      if (e && e.tooLarge)
        return refusal(function (pageText) {
          return pageText('share link: the preset in #z= inflates to more than %s, the limit for a preset; stopped there',
                          sizeText(maxPresetBytes));
        });
      return refusal(function (pageText) {
        return pageText('share link: the text after #%s= does not decompress (the link may have been cut short)', key);
      });
    });
  }

  return { fragment: fragment, read: read, toBase64url: toBase64url, fromBase64url: fromBase64url,
           canCompress: canCompress, maxPresetBytes: maxPresetBytes, tooLarge: tooLarge };
})();
