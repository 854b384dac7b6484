#pragma once
// Uniform cells (edge >= interaction range) over a box, filled by a counting sort in O(N).
// Candidate pairs are found by scanning the 27 neighbour cells of each owned particle.
#include "vp/core/Vec3.hpp"
#include <cmath>
#include <cstddef>
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
    for (int cz = 0; cz < n_[2]; ++cz)
      for (int cy = 0; cy < n_[1]; ++cy)
        for (int cx = 0; cx < n_[0]; ++cx) {
          const int c = cx + n_[0] * (cy + n_[1] * cz);
          for (std::size_t a = start_[c]; a < start_[c + 1]; ++a) {
            const std::size_t i = item_[a];
            if (i >= nOwned) continue;
            for (int dz = -1; dz <= 1; ++dz) {
              const int z = cz + dz;
              if (z < 0 || z >= n_[2]) continue;
              for (int dy = -1; dy <= 1; ++dy) {
                const int y = cy + dy;
                if (y < 0 || y >= n_[1]) continue;
                for (int dx = -1; dx <= 1; ++dx) {
                  const int xx = cx + dx;
                  if (xx < 0 || xx >= n_[0]) continue;
                  const int nc = xx + n_[0] * (y + n_[1] * z);
                  for (std::size_t b = start_[nc]; b < start_[nc + 1]; ++b) {
                    const std::size_t j = item_[b];
                    if (j < nOwned && j <= i) continue;
                    f(i, j);
                  }
                }
              }
            }
          }
        }
  }


private:
  int cellIndex(const Vec3& p) const;
  int n_[3] = {0, 0, 0};
  Vec3 lo_;
  double inv_[3] = {0, 0, 0};
  std::vector<std::size_t> start_, item_;
  std::vector<int> cellOf_;
};

} // namespace vp
