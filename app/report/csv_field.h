#pragma once
// One CSV field, the one rule behind every CSV swarmlab writes (run --csv, the figures' CSV,
// merge's runs.csv, the app's exports): every field in double quotes, a quote inside doubled
// (RFC 4180), so a comma, a quote or a line break in a name never splits a row; and text that
// a spreadsheet would run as a formula shown as text instead (OWASP's rule against CSV
// injection). Rows end in "\n" (RFC 4180 names CRLF; every reader takes both).

#include <string>
#include <string_view>

namespace swarmlab::report {

/// Text that is not the program's own (a value name from a run record, a sweep's key, a
/// legend): quoted, and when it starts with '=', '+', '-', '@', a tab or a carriage return,
/// prefixed with a single quote, which a spreadsheet shows as the text it is.
std::string csv_text(std::string_view text);

/// A number the program formats itself: quoted, never prefixed. Its characters are digits, a
/// sign, a point and an exponent ("-1.5", "2.5e-07", "nan", "inf", "-inf"): a spreadsheet reads
/// it as a number, never as a formula, and a prefix would turn -1.5 into text.
std::string csv_number(double x, int significant_digits = 17);

/// A number already written as text (an integer, or a JSON number): quoted like csv_number.
/// Anything that is not made of a number's characters is written as csv_text instead, so a
/// caller cannot let a formula through by mistake.
std::string csv_number_text(std::string_view number);

}  // namespace swarmlab::report
