#pragma once
// Uniform cells (edge >= interaction range) laid over a box, stored only where particles are:
// a dense array over the bounding box of the particles' cells while that box holds at most a few
// cells per particle (a counting sort in O(N)), a hash of the occupied cells otherwise (a few large
// spheres or a dilute suspension in a big domain). Memory and time follow the particles, not the
// box; both layouts give the same candidate pairs. Candidates are found by scanning the 27
// neighbour cells of each owned particle.
#include "vp/core/Vec3.hpp"
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vp {

class CellBuckets {
public:
  // Points outside [lo, hi] go to the nearest edge cell, which keeps the search complete.
  void build(const std::vector<Vec3>& x, std::size_t n, const Vec3& lo, const Vec3& hi, double cellSize);

  // Calls f(i, j) once for every unordered pair with i owned (i < nOwned) and either j owned
  // (j > i) or j a ghost (j >= nOwned), whose cells touch. The caller applies the distance test.
  template <class F>
  void forEachCandidate(std::size_t nOwned, F&& f) const
  {
    if (hashed_)
      scan<true>(nOwned, f);
    else
      scan<false>(nOwned, f);
  }

  bool hashed() const { return hashed_; }
  std::size_t cellsStored() const { return hashed_ ? occupied_.size() : start_.size() - 1; }

private:
  using Coord = std::array<std::int64_t, 3>;  // cell coordinates relative to the occupied box
  struct Cell {
    Coord c;
    std::size_t begin, end;  // its particles: item_[begin, end)
  };

  std::int64_t key(const Coord& c) const { return c[0] + m_[0] * (c[1] + m_[1] * c[2]); }
  // The particles of the cell at c, [begin, end); empty outside the occupied box.
  template <bool Hashed>
  std::pair<std::size_t, std::size_t> range(const Coord& c) const
  {
    for (int d = 0; d < 3; ++d)
      if (c[d] < 0 || c[d] >= m_[d]) return {0, 0};
    if constexpr (Hashed) {
      const auto it = index_.find(key(c));
      if (it == index_.end()) return {0, 0};
      return {occupied_[it->second].begin, occupied_[it->second].end};
    } else {
      const std::size_t k = static_cast<std::size_t>(key(c));
      return {start_[k], start_[k + 1]};
    }
  }

  template <bool Hashed, class F>
  void scan(std::size_t nOwned, F& f) const
  {
    for (const Cell& cell : occupied_)
      for (std::size_t a = cell.begin; a < cell.end; ++a) {
        const std::size_t i = item_[a];
        if (i >= nOwned) continue;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const auto [begin, end] = range<Hashed>({cell.c[0] + dx, cell.c[1] + dy, cell.c[2] + dz});
              for (std::size_t b = begin; b < end; ++b) {
                const std::size_t j = item_[b];
                if (j < nOwned && j <= i) continue;
                f(i, j);
              }
            }
      }
  }

  bool hashed_ = false;
  std::int64_t m_[3] = {0, 0, 0};                  // cells of the occupied box per axis
  std::vector<std::size_t> item_;                  // particle indices grouped by cell
  std::vector<Cell> occupied_;                     // the non-empty cells
  std::vector<std::size_t> start_;                 // dense: item_ range of every cell of the box
  std::unordered_map<std::int64_t, std::size_t> index_;  // hashed: key -> occupied_ index
  std::vector<Coord> cellOf_;
  std::vector<std::int64_t> keyOf_;
};

} // namespace vp
