#include "vp/particles/CellBuckets.hpp"
#include <algorithm>

namespace vp {

int CellBuckets::cellIndex(const Vec3& p) const
{
  int c[3];
  for (int d = 0; d < 3; ++d) {
    const int k = static_cast<int>(std::floor((p[d] - lo_[d]) * inv_[d]));
    c[d] = std::min(std::max(k, 0), n_[d] - 1);
  }
  return c[0] + n_[0] * (c[1] + n_[1] * c[2]);
}

void CellBuckets::build(const std::vector<Vec3>& x, std::size_t n, const Vec3& lo, const Vec3& hi, double cellSize)
{
  lo_ = lo;
  for (int d = 0; d < 3; ++d) {
    // At least one cell; cells never smaller than the range (the box is divided, not padded).
    n_[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d]) / cellSize)));
    inv_[d] = n_[d] / (hi[d] - lo[d]);
  }
  const std::size_t nc = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  start_.assign(nc + 1, 0);
  cellOf_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    cellOf_[i] = cellIndex(x[i]);
    ++start_[cellOf_[i] + 1];
  }
  for (std::size_t c = 0; c < nc; ++c) start_[c + 1] += start_[c];
  item_.resize(n);
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) item_[fill[cellOf_[i]]++] = i;
}

} // namespace vp
