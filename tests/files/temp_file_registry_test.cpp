// The temporaries an interrupted process leaves: none (app/files/temp_file_registry.h). Each
// case forks a child that registers a file and receives a signal. Native only (no fork in wasm).
#ifndef __EMSCRIPTEN__
#include "files/temp_file_registry.h"

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <string>

namespace {

std::string scratch_file(const char* name) {
  const std::string path = "/tmp/temp_file_registry_test." + std::to_string(::getpid()) + name;
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fclose(f);
  return path;
}

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

/// Forks; the child runs body then exits 7 if still alive. Returns the child's wait status.
template <class Body>
int in_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    ::_exit(7);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST_CASE(
    "temp_file_registry: SIGTERM and SIGINT remove the registered files, then end the process") {
  for (int signal : {SIGTERM, SIGINT}) {
    const std::string temp = scratch_file(".temp"), kept = scratch_file(".kept"),
                      renamed = scratch_file(".renamed");
    const int status = in_child([&] {
      std::signal(signal, SIG_DFL);
      swarmlab::register_temp_file(temp);
      swarmlab::register_temp_file(renamed);
      swarmlab::unregister_temp_file(renamed);  // renamed into place: no longer ours to remove
      std::raise(signal);
    });
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal);  // the shell's 128 + signal
    CHECK_FALSE(exists(temp));
    CHECK(exists(kept));
    CHECK(exists(renamed));
    std::remove(kept.c_str());
    std::remove(renamed.c_str());
  }
}

TEST_CASE("temp_file_registry: a SIGINT the process ignores stays ignored, and the file stays") {
  const std::string temp = scratch_file(".ignored");
  const int status = in_child([&] {
    std::signal(SIGINT, SIG_IGN);  // a shell's background job
    swarmlab::register_temp_file(temp);
    std::raise(SIGINT);
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 7);
  CHECK(exists(temp));
  std::remove(temp.c_str());
}
#endif
