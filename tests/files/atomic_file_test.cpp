// Output files that cannot hurt (app/files/atomic_file.h), checked on real files in a scratch
// folder. Native only: the wasm build's file system has no FIFOs or hard links to test with.
#ifndef __EMSCRIPTEN__
#include "files/atomic_file.h"

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using swarmlab::OutputFiles;

namespace {

/// A fresh folder, removed at the end of the test.
struct Scratch {
  fs::path dir;
  Scratch() {
    char name[] = "/tmp/atomic_file_test.XXXXXX";
    dir = ::mkdtemp(name);
  }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
  std::set<std::string> names() const {
    std::set<std::string> out;
    for (const auto& entry : fs::directory_iterator(dir)) out.insert(entry.path().filename());
    return out;
  }
};

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("atomic_file: a new file and a replaced file hold exactly what was written") {
  Scratch s;
  CHECK(swarmlab::write_file_atomically(s / "new.txt", "first") == "");
  CHECK(text_of(s / "new.txt") == "first");
  CHECK(swarmlab::write_file_atomically(s / "new.txt", "second") == "");
  CHECK(text_of(s / "new.txt") == "second");
  CHECK(s.names() == std::set<std::string>{"new.txt"});
}

TEST_CASE("atomic_file: a replaced file keeps its permissions") {
  Scratch s;
  put(s / "script", "old");
  ::chmod((s / "script").c_str(), 0751);
  CHECK(swarmlab::write_file_atomically(s / "script", "new") == "");
  struct stat st {};
  REQUIRE(::stat((s / "script").c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0751);
}

TEST_CASE("atomic_file: a symlink is written through and stays a link") {
  Scratch s;
  put(s / "real", "old");
  fs::create_symlink("real", s / "link");
  CHECK(swarmlab::write_file_atomically(s / "link", "new") == "");
  CHECK(fs::is_symlink(s / "link"));
  CHECK(text_of(s / "real") == "new");
  fs::create_symlink("nowhere", s / "dangling");
  CHECK(swarmlab::check_output_path(s / "dangling").find("symlink to nothing") !=
        std::string::npos);
}

TEST_CASE("atomic_file: a directory, a FIFO or a missing folder is refused and left as it was") {
  Scratch s;
  fs::create_directory(s / "dir");
  REQUIRE(::mkfifo((s / "fifo").c_str(), 0644) == 0);
  CHECK(swarmlab::check_output_path(s / "dir").find("is a directory") != std::string::npos);
  // Refused without opening it: opening a FIFO for writing would wait for a reader forever.
  CHECK(swarmlab::write_file_atomically(s / "fifo", "x").find("FIFO") != std::string::npos);
  CHECK(fs::is_fifo(s / "fifo"));
  CHECK(fs::is_directory(s / "dir"));
  CHECK(swarmlab::check_output_path(s / "no/such.txt").find("does not exist") != std::string::npos);
  CHECK(swarmlab::check_output_path("/dev/null").find("device") != std::string::npos);
  CHECK(s.names() == std::set<std::string>{"dir", "fifo"});
}

TEST_CASE("atomic_file: the same file twice is refused, however it is spelled") {
  Scratch s;
  put(s / "a", "a");
  fs::create_hard_link(s / "a", s / "hard");
  fs::create_symlink("a", s / "soft");
  CHECK(swarmlab::check_output_paths({s / "a", s / "b"}) == "");
  CHECK(swarmlab::check_output_paths({s / "a", s / "hard"}).find("given twice") !=
        std::string::npos);
  CHECK(swarmlab::check_output_paths({s / "soft", s / "a"}).find("given twice") !=
        std::string::npos);
  CHECK(swarmlab::check_output_paths({s / "new", s / "./new"}).find("given twice") !=
        std::string::npos);
}

TEST_CASE("atomic_file: outputs not committed leave no file behind and the old ones as they were") {
  Scratch s;
  put(s / "a", "old-a");
  {
    OutputFiles files;
    CHECK(files.stage(s / "a", "new-a") == "");
    CHECK(files.stage(s / "b", "new-b") == "");
    CHECK(s.names().size() == 3);  // a and two temporaries
  }
  CHECK(s.names() == std::set<std::string>{"a"});
  CHECK(text_of(s / "a") == "old-a");
}

TEST_CASE("atomic_file: when one rename fails, the files already replaced are put back") {
  Scratch s;
  put(s / "a", "old-a");
  put(s / "c", "old-c");
  OutputFiles files;
  CHECK(files.stage(s / "a", "new-a") == "");
  CHECK(files.stage(s / "new", "new") == "");
  CHECK(files.stage(s / "c", "new-c") == "");
  // The last temporary disappears before the commit: its rename fails after two succeeded.
  ::unlink(files.temp_of(s / "c").c_str());
  CHECK(files.commit().find("cannot move into place") != std::string::npos);
  CHECK(text_of(s / "a") == "old-a");
  CHECK(text_of(s / "c") == "old-c");
  CHECK(s.names() == std::set<std::string>{"a", "c"});
}
#endif
