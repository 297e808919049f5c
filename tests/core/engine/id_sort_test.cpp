#include "engine/id_sort.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

TEST_CASE("sort_by_id puts a step's hits in the order std::sort does") {
  std::mt19937_64 rng(7);
  for (const std::size_t ids : {std::size_t(100), std::size_t(40000), std::size_t(1) << 26}) {
    for (const std::size_t hits : {0, 1, 63, 64, 190, 5000}) {
      if (hits > ids) continue;
      // Unique ids drawn from [first, first + ids), as a lane's hits are.
      const std::uint32_t first = std::uint32_t(rng() % 1000000);
      std::vector<std::uint32_t> chosen;
      while (chosen.size() < hits) {
        const auto id = std::uint32_t(first + rng() % ids);
        if (std::find(chosen.begin(), chosen.end(), id) == chosen.end()) chosen.push_back(id);
      }
      std::vector<std::uint64_t> keys, scratch;
      for (std::size_t h = 0; h < chosen.size(); ++h)
        keys.push_back(std::uint64_t(chosen[h]) << 32 | h);
      std::vector<std::uint64_t> expected = keys;
      std::sort(expected.begin(), expected.end());
      swarm::fast::sort_by_id(keys, scratch);
      INFO("ids " << ids << ", hits " << hits);
      CHECK(keys == expected);
    }
  }
}
