#pragma once
// Sorting a step's hits into particle-id order, which the fast engine combines them in: a
// radix sort, since std::sort's comparisons cost the fireball (about 190 hits a lane a step)
// a tenth of its time.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace swarm::fast {

/// Sorts keys of the form id << 32 | place, the ids unique, into increasing order (the order
/// std::sort gives them); scratch is working space. Short lists go to std::sort.
inline void sort_by_id(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch) {
  constexpr std::size_t kRadixFrom = 64;
  const std::size_t n = keys.size();
  if (n < kRadixFrom) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  std::uint32_t lowest = ~std::uint32_t(0), highest = 0;
  for (const std::uint64_t key : keys) {
    const auto id = std::uint32_t(key >> 32);
    lowest = std::min(lowest, id);
    highest = std::max(highest, id);
  }
  const std::uint32_t span = highest - lowest;
  scratch.resize(n);
  // Least significant byte of id - lowest first; each pass is stable, so the last one leaves
  // the keys in id order. The ids of one lane span its share of N: two passes for 40,000.
  for (int shift = 0; shift < 32 && (span >> shift) != 0; shift += 8) {
    std::array<std::uint32_t, 257> start{};
    for (const std::uint64_t key : keys)
      ++start[(((std::uint32_t(key >> 32) - lowest) >> shift) & 0xff) + 1];
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (const std::uint64_t key : keys)
      scratch[start[((std::uint32_t(key >> 32) - lowest) >> shift) & 0xff]++] = key;
    keys.swap(scratch);
  }
}

}  // namespace swarm::fast
