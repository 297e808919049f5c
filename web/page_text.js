// The page's own texts (web/shell.html's loading, errors and message line, and what the page's
// scripts show) in the reader's language, from the same tables as the app (assets/i18n/*.json,
// keyed by the English text; docs/i18n.md). build/web/page_texts.js, generated at build time by
// scripts/i18n.py page and loaded just before this, holds the languages (window.swarmlabLanguages:
// the rows of assets/i18n/languages.json) and only the keys the page uses
// (window.swarmlabPageTexts).
//
//   pageText(english)                         the text in the page's language, else the English
//   pageText(english, value, ...)             each %s, %d or %.1f in it filled by the next value
//   window.swarmlabLanguage                   the code of the language chosen (a row of
//                                             languages.json, the pseudo-language's for layout tests)
//
// The language: #lang=CODE in the address, else localStorage 'swarmlab.language', else the
// first of navigator.languages that fits, by swarmlab::language_for_locale's rule (a locale's
// primary subtag among a language's aliases), else the first language (the texts' own).
// scripts/i18n.py extract collects the keys: every pageText call whose first argument is one
// string literal (in single or double quotes) in web/*.js and web/shell.html.
(function () {
  'use strict';
  var rows = window.swarmlabLanguages || [];
  var source = rows.length ? rows[0] : null;
  var pseudo = null;
  for (var r = 0; r < rows.length; ++r) if (rows[r].pseudo) pseudo = rows[r];

  function row(code) {
    for (var i = 0; i < rows.length; ++i) if (rows[i].code === code) return rows[i];
    return null;
  }

  /// The listed language whose aliases hold a locale's primary subtag, or null when none does.
  function fits(locale) {
    var primary = String(locale || '').split(/[.@]/)[0].toLowerCase().replace(/_/g, '-').split('-')[0];
    for (var i = 0; i < rows.length; ++i)
      if (!rows[i].pseudo && rows[i].aliases.indexOf(primary) >= 0) return rows[i].code;
    return null;
  }

  /// A code as given (#lang=, the stored choice): exact (the pseudo-language's too, regardless
  /// of case for a listed one), or by the locale rule; null if none.
  function known(code) {
    if (!code) return null;
    if (pseudo && code === pseudo.code) return code;
    for (var i = 0; i < rows.length; ++i)
      if (!rows[i].pseudo && rows[i].code.toLowerCase() === String(code).toLowerCase()) return rows[i].code;
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

  // Without the table (page_texts.js not loaded) the page speaks the English it is written in.
  var language = fromAddress() || fromStorage() || fromBrowser() || (source ? source.code : '');
  var speaking = row(language);
  var isPseudo = !!(speaking && speaking.pseudo);
  window.swarmlabLanguage = language;
  /// The document's language for a code: the pseudo-language's texts are the source's, dressed up.
  window.swarmlabDocumentLanguage = function (code) {
    var r = row(code);
    return r && r.pseudo && source ? source.code : code;
  };
  if (document.documentElement && language) document.documentElement.lang = window.swarmlabDocumentLanguage(language);

  // The pseudo-language, as swarmlab::pseudo_text (app/i18n/translator.cpp): letters accented,
  // about 1.6x as long, printf conversions kept.
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
    if (isPseudo) {
      shown = pseudoText(english);
    } else if (speaking && speaking !== source) {
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
    var comma = speaking && speaking.decimal_separator === ',';
    return comma ? String(text).replace(/(\d)\.(\d)/g, '$1,$2') : String(text);
  };
})();
