#include "vp/particles/CellBuckets.hpp"
#include <algorithm>
#include <limits>
#include <numeric>

namespace vp {

void CellBuckets::build(const std::vector<Vec3>& x, std::size_t n, const Vec3& lo, const Vec3& hi, double cellSize)
{
  // The cells of the whole box (never smaller than the range: the box is divided, not padded) ...
  std::int64_t N[3];
  double inv[3];
  for (int d = 0; d < 3; ++d) {
    N[d] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor((hi[d] - lo[d]) / cellSize)));
    inv[d] = N[d] / (hi[d] - lo[d]);
  }
  // ... of which only the box around the particles' cells is stored.
  Coord cmin, cmax;
  cmin.fill(std::numeric_limits<std::int64_t>::max());
  cmax.fill(0);
  cellOf_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      const double k = std::floor((x[i][d] - lo[d]) * inv[d]);
      // NaN goes to cell 0 too (the health check stops the run after the step).
      cellOf_[i][d] = !(k >= 0) ? 0 : k >= N[d] ? N[d] - 1 : static_cast<std::int64_t>(k);
      cmin[d] = std::min(cmin[d], cellOf_[i][d]);
      cmax[d] = std::max(cmax[d], cellOf_[i][d]);
    }
  if (n == 0) cmin.fill(0);
  for (int d = 0; d < 3; ++d) m_[d] = cmax[d] - cmin[d] + 1;
  keyOf_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) cellOf_[i][d] -= cmin[d];
    keyOf_[i] = key(cellOf_[i]);
  }
  const double cells = double(m_[0]) * double(m_[1]) * double(m_[2]);
  hashed_ = cells > std::max(4096.0, 8.0 * double(n));
  occupied_.clear();
  index_.clear();
  item_.resize(n);
  if (!hashed_) {
    // Counting sort over the dense box.
    const std::size_t nc = static_cast<std::size_t>(cells);
    start_.assign(nc + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++start_[keyOf_[i] + 1];
    for (std::size_t c = 0; c < nc; ++c) start_[c + 1] += start_[c];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) item_[fill[keyOf_[i]]++] = i;
    for (std::size_t c = 0; c < nc; ++c)
      if (start_[c] < start_[c + 1]) {
        const std::int64_t k = static_cast<std::int64_t>(c);
        occupied_.push_back({Coord{k % m_[0], (k / m_[0]) % m_[1], k / (m_[0] * m_[1])}, start_[c], start_[c + 1]});
      }
    return;
  }
  // Hashed: particles sorted by cell (ascending index within a cell, as the counting sort gives).
  start_.clear();
  std::iota(item_.begin(), item_.end(), std::size_t(0));
  std::stable_sort(item_.begin(), item_.end(), [&](std::size_t a, std::size_t b) { return keyOf_[a] < keyOf_[b]; });
  for (std::size_t a = 0; a < n;) {
    std::size_t b = a + 1;
    while (b < n && keyOf_[item_[b]] == keyOf_[item_[a]]) ++b;
    index_[keyOf_[item_[a]]] = occupied_.size();
    occupied_.push_back({cellOf_[item_[a]], a, b});
    a = b;
  }
}

} // namespace vp
