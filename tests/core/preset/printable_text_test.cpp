#include "swarm/preset/printable_text.h"

#include <doctest/doctest.h>

using namespace swarm;

TEST_CASE("printable escapes what a terminal would obey and keeps the rest") {
  CHECK(printable("Fig. 1: four masses") == "Fig. 1: four masses");
  CHECK(printable("\x1b]0;pwned\x07\x1b[2J") == "\\u001b]0;pwned\\u0007\\u001b[2J");
  CHECK(printable("a\nb\tc\x7f") == "a\\nb\\tc\\u007f");
  // UTF-8 text stays; the C1 control U+009B (a one-character CSI) and stray bytes do not.
  CHECK(printable("Ω = √(J M)") == "Ω = √(J M)");
  CHECK(printable("\xc2\x9b"
                  "2J") == "\\u009b2J");
  CHECK(printable("\xff\xc3") == "\\xff\\xc3");
}

TEST_CASE("printable cuts long text after about max_bytes") {
  const std::string long_text(1'000'000, 'x');
  const std::string cut = printable(long_text, 40);
  CHECK(cut == std::string(40, 'x') + "...");
  CHECK(printable(std::string(40, 'y'), 40) == std::string(40, 'y'));
  // A multi-byte character is never split.
  const std::string omegas = printable("ΩΩΩΩΩ", 3);
  CHECK(omegas == "ΩΩ...");
}
