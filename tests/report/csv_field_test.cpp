#include "report/csv_field.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarmlab::report;

TEST_CASE("csv field: text is quoted, its quotes doubled, a line break kept inside the quotes") {
  CHECK(csv_text("P") == "\"P\"");
  CHECK(csv_text("") == "\"\"");
  CHECK(csv_text("a,b") == "\"a,b\"");
  CHECK(csv_text("say \"hi\"\nthere") == "\"say \"\"hi\"\"\nthere\"");
}

TEST_CASE("csv field: text a spreadsheet would run as a formula starts with a quote mark") {
  // OWASP, CSV injection: = + - @ tab and carriage return at the start.
  CHECK(csv_text("=HYPERLINK(\"http://x\")") == "\"'=HYPERLINK(\"\"http://x\"\")\"");
  CHECK(csv_text("+1") == "\"'+1\"");
  CHECK(csv_text("-2+3") == "\"'-2+3\"");
  CHECK(csv_text("@SUM(A1)") == "\"'@SUM(A1)\"");
  CHECK(csv_text("\t=1") == "\"'\t=1\"");
  CHECK(csv_text("\r=1") == "\"'\r=1\"");
  CHECK(csv_text("a=1") == "\"a=1\"");  // only the first character counts
}

TEST_CASE("csv field: the program's numbers stay numbers, negative ones too") {
  CHECK(csv_number(-1.5) == "\"-1.5\"");
  CHECK(csv_number(1.0 / 3) == "\"0.33333333333333331\"");
  CHECK(csv_number(1.0 / 3, 8) == "\"0.33333333\"");
  CHECK(csv_number(-2.5e-7) == "\"-2.4999999999999999e-07\"");
  CHECK(csv_number(NAN) == "\"nan\"");
  CHECK(csv_number(-INFINITY) == "\"-inf\"");
  CHECK(csv_number_text("-12") == "\"-12\"");
  CHECK(csv_number_text("2.5E+3") == "\"2.5E+3\"");
  // Text that only looks like a number at the start is text, neutralised.
  CHECK(csv_number_text("-1+cmd|' /C calc'!A0") == "\"'-1+cmd|' /C calc'!A0\"");
  CHECK(csv_number_text("-") == "\"'-\"");
  CHECK(csv_number_text("1e") == "\"1e\"");
}
