#include "ui/input/region_cycle.h"

namespace swarmlab {

std::optional<std::size_t> next_region(std::optional<std::size_t> current,
                                       const std::vector<bool>& shown, int direction) {
  const long n = long(shown.size());
  if (n == 0) return std::nullopt;
  const long step = direction < 0 ? -1 : 1;
  long i = current && long(*current) < n ? long(*current) : (step > 0 ? -1 : n);
  for (long k = 0; k < n; ++k) {
    i = ((i + step) % n + n) % n;
    if (shown[std::size_t(i)]) return std::size_t(i);
  }
  return std::nullopt;
}

}  // namespace swarmlab
