// libFuzzer target: any bytes through the reader of an ensemble's run records (what `swarmlab
// merge` and a resumed `swarmlab ensemble` read from DIR/runs/). scripts/fuzz.sh builds and
// runs it, seeded with a few valid records (tests/fuzz/run_records/).
//
// What must hold for every input:
// - a refusal is one short line of printable text naming what is wrong;
// - an accepted record carries the digest of its own canonical text, survives a round trip
//   through record_json to the same canonical text, and has series of equal lengths.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ensemble/run_record.h"

namespace {

void expect(bool ok, const char* what, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: %s\n%s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swarmlab::ensemble;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const RecordRead read = parse_record(text);
  if (!read.record) {
    expect(!read.error.empty(), "a refusal without a message", text);
    expect(read.error.find('\n') == std::string::npos, "a refusal of more than one line", read.error);
    return 0;
  }
  const RunRecord& r = *read.record;
  expect(read.error.empty(), "an accepted record with an error", read.error);
  expect(r.P.size() == r.t.size() && r.T.size() == r.t.size() && r.R.size() == r.t.size() &&
             r.stage_P.size() == r.stage_V.size() && r.stage_T.size() == r.stage_V.size(),
         "series of different lengths accepted", text);
  const RecordRead again = parse_record(record_json(r));
  expect(again.record.has_value(), "an accepted record fails its own round trip", again.error);
  expect(canonical_text(*again.record) == canonical_text(r), "the round trip changes the record",
         canonical_text(r));
  return 0;
}
