#include "files/temp_file_registry.h"

#include <signal.h>
#include <unistd.h>

#include <climits>
#include <csignal>
#include <cstring>
#include <mutex>
#include <utility>

namespace swarmlab {
namespace {

// A fixed table, because a signal handler may not allocate or take a lock: a slot's path is
// written before its flag is raised, and the handler reads only slots whose flag is up.
constexpr int kSlots = 64;
char slot_path[kSlots][PATH_MAX];
volatile std::sig_atomic_t slot_used[kSlots];

struct sigaction previous_int, previous_term;
// Threads (an ensemble's runs) register files at once: one at a time claims a slot. The
// handler takes no lock; it reads only raised flags.
std::mutex slots_lock;

void remove_temp_files(int number) {
  for (int i = 0; i < kSlots; ++i)
    if (slot_used[i]) ::unlink(slot_path[i]);
  // Hand the signal back to whoever had it (by default: terminate with 128 + signal). The
  // raised signal is delivered once this handler returns.
  sigaction(number, number == SIGINT ? &previous_int : &previous_term, nullptr);
  raise(number);
}

/// Puts remove_temp_files on SIGINT and SIGTERM where it is not there yet (another library, or
/// a test, may have set its own since), keeping what was there to hand the signal on to.
void install_handlers() {
  struct sigaction action {};
  action.sa_handler = remove_temp_files;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  const std::pair<int, struct sigaction*> handled[] = {{SIGINT, &previous_int},
                                                       {SIGTERM, &previous_term}};
  for (const auto& [number, previous] : handled) {
    struct sigaction current {};
    sigaction(number, nullptr, &current);
    // A signal the process ignores (SIGINT for a shell's background job) stays ignored: the
    // write then goes on to the end, and its temporaries are renamed, not left behind.
    if (current.sa_handler == remove_temp_files || current.sa_handler == SIG_IGN) continue;
    *previous = current;
    sigaction(number, &action, nullptr);
  }
}

}  // namespace

bool register_temp_file(const std::string& path) {
  if (path.size() >= PATH_MAX) return false;
  std::lock_guard<std::mutex> hold(slots_lock);
  install_handlers();
  for (int i = 0; i < kSlots; ++i)
    if (!slot_used[i]) {
      std::memcpy(slot_path[i], path.c_str(), path.size() + 1);
      slot_used[i] = 1;
      return true;
    }
  return false;
}

void unregister_temp_file(const std::string& path) {
  std::lock_guard<std::mutex> hold(slots_lock);
  for (int i = 0; i < kSlots; ++i)
    if (slot_used[i] && path == slot_path[i]) {
      slot_used[i] = 0;
      return;
    }
}

}  // namespace swarmlab
