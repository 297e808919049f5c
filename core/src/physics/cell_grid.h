#pragma once
// A neighbour structure: particles sorted into cubic cells at least as wide as the contact
// distance, so that every pair closer than that lies in the same cell or in adjacent ones, and
// finding them costs O(N) rather than O(N^2). Rebuilt every step (a counting sort); the
// storage is kept between builds.

#include <cstdint>
#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

class CellGrid {
 public:
  /// Sorts the particles into cells of side >= min_side (> 0) over the box that holds them.
  /// At most about 2 N cells, so an extended swarm gets wider cells, never more memory.
  void build(const std::vector<Particle>& particles, double min_side);

  /// Calls close(i, j) once for every pair (i, j) in the same or adjacent cells: every pair
  /// closer than min_side, and others. The order is fixed by the cells and the indices.
  template <class Close>
  void for_each_neighbour_pair(Close&& close) const;

  int cells_per_side() const { return n_; }

 private:
  int n_ = 1;                       ///< cells along each axis
  std::vector<std::uint32_t> start_;  ///< first slot of each cell in order_, plus the end
  std::vector<std::uint32_t> order_;  ///< particle indices sorted by cell
  std::vector<std::uint32_t> cell_;   ///< each particle's cell
  std::vector<std::uint32_t> fill_;   ///< the next free slot of each cell while sorting
};

template <class Close>
void CellGrid::for_each_neighbour_pair(Close&& close) const {
  // The cell itself and the 13 neighbours ahead of it in (z, y, x) order: each adjacent pair
  // of cells is visited once.
  static constexpr int kAhead[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},  {-1, -1, 1},
                                        {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},  {1, 0, 1},
                                        {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};
  const int n = n_;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::uint32_t c = std::uint32_t((z * n + y) * n + x);
        const std::uint32_t b = start_[c], e = start_[c + 1];
        if (b == e) continue;
        for (std::uint32_t s = b; s < e; ++s)
          for (std::uint32_t t = s + 1; t < e; ++t) close(order_[s], order_[t]);
        for (const auto& d : kAhead) {
          const int X = x + d[0], Y = y + d[1], Z = z + d[2];
          if (X < 0 || Y < 0 || X >= n || Y >= n || Z >= n) continue;
          const std::uint32_t o = std::uint32_t((Z * n + Y) * n + X);
          for (std::uint32_t s = b; s < e; ++s)
            for (std::uint32_t t = start_[o]; t < start_[o + 1]; ++t) close(order_[s], order_[t]);
        }
      }
}

}  // namespace swarm
