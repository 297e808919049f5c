#include "report/csv_field.h"

#include <cmath>
#include <cstdio>

namespace swarmlab::report {
namespace {

std::string quoted(std::string_view text, bool as_text) {
  std::string out = "\"";
  if (!text.empty() && (text[0] == '=' || text[0] == '+' || text[0] == '-' || text[0] == '@' ||
                        text[0] == '\t' || text[0] == '\r') && as_text)
    out += '\'';
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// A number's text: an optional sign, then digits with at most one point and an exponent, or
/// nan / inf as printf writes them.
bool is_number_text(std::string_view s) {
  std::size_t i = s.empty() || (s[0] != '-' && s[0] != '+') ? 0 : 1;
  const std::string_view body = s.substr(i);
  if (body == "nan" || body == "inf") return true;
  bool digits = false, point = false;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] >= '0' && s[i] <= '9') digits = true;
    else if (s[i] == '.' && !point) point = true;
    else return false;
  }
  if (!digits) return false;
  if (i == s.size()) return true;
  ++i;  // the exponent: a sign and digits
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

}  // namespace

std::string csv_text(std::string_view text) { return quoted(text, true); }

std::string csv_number(double x, int significant_digits) {
  if (std::isnan(x)) return "\"nan\"";  // printf may write -nan, the sign says nothing
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, x);
  return quoted(buf, false);
}

std::string csv_number_text(std::string_view number) {
  return quoted(number, !is_number_text(number));
}

}  // namespace swarmlab::report
