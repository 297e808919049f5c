// The page's own texts (web/shell.html's loading, errors and message line, and what the page's
// scripts show) in the reader's language, from the same tables as the app (assets/i18n/*.json,
// keyed by the English text; docs/i18n.md). Loaded first by shell.html; build/web/page_texts.js,
// generated at build time with only the keys the page uses, fills window.swarmlabPageTexts.
//
//   pageText(english)                         the text in the page's language, else the English
//   pageText(english, value, ...)             each %s, %d or %.1f in it filled by the next value
//   window.swarmlabLanguage                   the language chosen: 'en', 'es', 'de', 'fr',
//                                             'pt-BR', 'zh-CN' (or 'x-pseudo' for layout tests)
//
// The language: #lang=CODE in the address, else localStorage 'swarmlab.language', else the
// first of navigator.languages that fits, by swarmlab::language_for_locale's rule
// (app/i18n/language.cpp: es-MX -> es, pt and pt-PT -> pt-BR, zh* -> zh-CN), else English.
// scripts/i18n.py extract collects the keys: every pageText call whose first argument is one
// string literal (in single or double quotes) in web/*.js and web/shell.html.
(function () {
  'use strict';
  var listed = ['en', 'es', 'de', 'fr', 'pt-BR', 'zh-CN'];
  var pseudo = 'x-pseudo';

  /// The listed language that best fits a locale or language tag, or null when none does.
  function fits(locale) {
    var tag = String(locale || '').split(/[.@]/)[0].toLowerCase().replace(/_/g, '-');
    var primary = tag.split('-')[0];
    if (primary === 'pt') return 'pt-BR';
    if (primary === 'zh') return 'zh-CN';
    for (var i = 0; i < listed.length; ++i)
      if (listed[i].toLowerCase() === primary) return listed[i];
    return null;
  }

  /// A code as given (#lang=, the stored choice): exact, or by the locale rule; null if none.
  function known(code) {
    if (!code) return null;
    if (code === pseudo) return pseudo;
    for (var i = 0; i < listed.length; ++i)
      if (listed[i].toLowerCase() === String(code).toLowerCase()) return listed[i];
    return fits(code);
  }

  function fromAddress() {
    try {
      var parts = String(location.hash || '').replace(/^#/, '').split('&');
      for (var i = 0; i < parts.length; ++i)
        if (parts[i].indexOf('lang=') === 0) return known(decodeURIComponent(parts[i].slice(5)));
    } catch (e) { /* no address */ }
    return null;
  }

  function fromStorage() {
    try { return known(window.localStorage.getItem('swarmlab.language')); } catch (e) { return null; }
  }

  function fromBrowser() {
    var tags = (navigator.languages && navigator.languages.length) ? navigator.languages
                                                                  : [navigator.language || ''];
    for (var i = 0; i < tags.length; ++i) {
      var code = fits(tags[i]);
      if (code) return code;
    }
    return null;
  }

  var language = fromAddress() || fromStorage() || fromBrowser() || 'en';
  window.swarmlabLanguage = language;
  if (document.documentElement) document.documentElement.lang = language === pseudo ? 'en' : language;

  // The pseudo-language, as swarmlab::pseudo_text: letters accented, about 1.6x as long.
  var accents = { a: 'à', e: 'é', i: 'î', o: 'õ', u: 'ü', c: 'ç', n: 'ñ', y: 'ý',
                  A: 'Å', E: 'É', I: 'Î', O: 'Ö', U: 'Û', C: 'Ç', N: 'Ñ' };
  var conversion = /%[-+ #0-9.*hlLzjt]*[a-zA-Z%]/g;
  function pseudoText(english) {
    var out = '[', at = 0, m;
    conversion.lastIndex = 0;
    while ((m = conversion.exec(english))) {
      out += english.slice(at, m.index).replace(/[a-zA-Z]/g, function (c) { return accents[c] || c; });
      out += m[0];
      at = m.index + m[0].length;
    }
    out += english.slice(at).replace(/[a-zA-Z]/g, function (c) { return accents[c] || c; });
    var filler = ['ë', 'ï', 'ô', 'â', 'û', ' '];
    var extra = Math.max(3, Math.ceil(0.6 * Array.from(english).length));
    for (var k = 0; k < extra; ++k) out += filler[k % 6];
    return out + ']';
  }

  /// Fills each printf conversion (%s, %d, %.1f ...) with the next value; %% is a percent sign.
  function fill(text, values) {
    var next = 0;
    return text.replace(conversion, function (c) {
      if (c === '%%') return '%';
      if (next >= values.length) return c;
      var value = values[next++];
      var precision = /\.(\d+)f$/.exec(c);
      if (precision && typeof value === 'number') return value.toFixed(Number(precision[1]));
      return String(value);
    });
  }

  var table = null;
  /// The text for `english` in the page's language (its translation, else the English), with
  /// the values after it put in its conversions.
  window.pageText = function (english) {
    var shown = english;
    if (language === pseudo) {
      shown = pseudoText(english);
    } else if (language !== 'en') {
      if (!table) table = (window.swarmlabPageTexts || {})[language] || null;
      if (table && typeof table[english] === 'string' && table[english]) shown = table[english];
    }
    return arguments.length > 1 ? fill(shown, Array.prototype.slice.call(arguments, 1)) : shown;
  };
  /// The English text with the values filled in, as pageText gives it in English: for messages
  /// the JS API returns (they stay English) next to what the page shows.
  window.pageTextEnglish = function (english) {
    return fill(english, Array.prototype.slice.call(arguments, 1));
  };
  /// A number as the page's language writes it: 7.5, or 7,5 where a comma separates decimals.
  window.pageNumber = function (text) {
    var comma = language === pseudo || /^(es|de|fr|pt-BR)$/.test(language);
    return comma ? String(text).replace(/(\d)\.(\d)/g, '$1,$2') : String(text);
  };
})();
