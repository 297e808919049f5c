#include "scenarios/process_memory.h"

#include <fstream>
#include <string>

namespace swarmlab::scenarios {
namespace {

std::optional<std::size_t> status_field(const char* name) {
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == name) {
      std::size_t kib = 0;
      in >> kib;
      return kib * 1024;
    }
    std::getline(in, key);
  }
#else
  (void)name;
#endif
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> peak_memory() { return status_field("VmHWM:"); }
std::optional<std::size_t> current_memory() { return status_field("VmRSS:"); }

void reset_peak_memory() {
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  std::ofstream("/proc/self/clear_refs") << "5";  // resets VmHWM to the current RSS
#endif
}

}  // namespace swarmlab::scenarios
