// The one reader of the CLI's input files (app/files/text_file.h), on real files in a scratch
// folder: only regular files, never more than the limit, never a wait on a FIFO. Native only:
// the wasm build's file system has no FIFOs or devices to test with.
#ifndef __EMSCRIPTEN__
#include "files/text_file.h"

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using swarmlab::read_regular_file;
using swarmlab::read_text_file;

namespace {

struct TextFileScratch {
  fs::path dir;
  TextFileScratch() {
    char name[] = "/tmp/text_file_test.XXXXXX";
    dir = ::mkdtemp(name);
  }
  ~TextFileScratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

TEST_CASE("text file: a regular file is read whole, a missing one named as missing") {
  TextFileScratch s;
  write_text(s / "a.json", std::string("{\"x\": 1}\0tail", 13));
  const swarmlab::TextFile a = read_regular_file(s / "a.json");
  CHECK(a.error.empty());
  CHECK(a.text == std::string("{\"x\": 1}\0tail", 13));
  const swarmlab::TextFile none = read_regular_file(s / "none.json");
  CHECK(none.missing);
  std::string error;
  CHECK(read_text_file(s / "none.json", error).empty());
  CHECK(error.rfind(s / "none.json: cannot open the file", 0) == 0);
}

TEST_CASE("text file: a FIFO is refused at once, without waiting for a writer") {
  TextFileScratch s;
  REQUIRE(::mkfifo((s / "plan.json").c_str(), 0600) == 0);
  const auto start = std::chrono::steady_clock::now();
  const swarmlab::TextFile f = read_regular_file(s / "plan.json");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(f.error == "not a regular file (a FIFO); only regular files are read");
  CHECK(!f.missing);
  CHECK(seconds < 5);
}

TEST_CASE("text file: a device behind a symlink and a folder are refused") {
  TextFileScratch s;
  fs::create_symlink("/dev/zero", s / "2.json");
  CHECK(read_regular_file(s / "2.json").error ==
        "not a regular file (a character device); only regular files are read");
  CHECK(read_regular_file(s.dir.string()).error ==
        "not a regular file (a folder); only regular files are read");
}

TEST_CASE("text file: a file over the limit is refused, the limit named") {
  TextFileScratch s;
  write_text(s / "big.json", std::string(100, 'x'));
  CHECK(read_regular_file(s / "big.json", 100).text.size() == 100);  // the limit itself is read
  CHECK(read_regular_file(s / "big.json", 99).error ==
        "larger than 99 bytes, the most this file may hold");
  // The default limit, named in MB.
  write_text(s / "huge.json", std::string(swarmlab::kTextFileLimit + 1, ' '));
  std::string error;
  read_text_file(s / "huge.json", error);
  CHECK(error == s / "huge.json: larger than 16 MB, the most this file may hold");
}
#endif
