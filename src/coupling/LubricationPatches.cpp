#include "vp/coupling/LubricationPatches.hpp"
#include <algorithm>

namespace vp {

void LubricationPatches::find(const ParticleStore& s)
{
  patches_.clear();
  replaced_.clear();
  atWalls_.clear();
  const std::size_t n = s.size();
  auto add = [&](std::size_t p, const Vec3& normal, double R, double a, double w) {
    patches_.push_back({p, normal, lub_.patchRadiusSquared(R, a), w});
  };
  double rmax = 0;
  Vec3 lo = n ? s.x[0] : Vec3{}, hi = lo;
  for (std::size_t p = 0; p < n; ++p) {
    rmax = std::max(rmax, s.radius[p]);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], s.x[p][d]);
      hi[d] = std::max(hi[d], s.x[p][d]);
    }
    for (int f = 0; f < 6; ++f) {
      const Wall& w = walls_[f];
      const double a = s.radius[p];
      const double weight = w.active ? lub_.replacementWeight(w.distance(s.x[p]) - a, a) : 0;
      if (!(weight > 0)) continue;
      add(p, -w.normal(), a, a, weight);
      replaced_.push_back({-1 - f, s.id[p], weight});  // a wall's key sorts first
      atWalls_.push_back(s.id[p]);
    }
  }
  if (n > 1) {
    // Every local pair, ghosts with ghosts too (all taken as owned by the search).
    buckets_.build(s.x, n, lo, hi, 2 * rmax + lub_.reach(rmax));
    buckets_.forEachCandidate(n, [&](std::size_t i, std::size_t j) {
      const Vec3 d = s.x[j] - s.x[i];
      const double r = norm(d), ai = s.radius[i], aj = s.radius[j], amin = std::min(ai, aj);
      const double weight = lub_.replacementWeight(r - ai - aj, amin);
      if (!(weight > 0) || s.id[i] == s.id[j]) return;
      const double R = ai * aj / (ai + aj);
      add(i, (1 / r) * d, R, amin, weight);
      add(j, (-1 / r) * d, R, amin, weight);
      replaced_.push_back({std::min(s.id[i], s.id[j]), std::max(s.id[i], s.id[j]), weight});
    });
  }
  std::stable_sort(patches_.begin(), patches_.end(), [](const Patch& a, const Patch& b) { return a.particle < b.particle; });
  begin_.assign(n + 1, 0);
  for (const Patch& q : patches_) ++begin_[q.particle + 1];
  for (std::size_t p = 0; p < n; ++p) begin_[p + 1] += begin_[p];
  std::sort(replaced_.begin(), replaced_.end());
  std::sort(atWalls_.begin(), atWalls_.end());
}

double LubricationPatches::replaced(std::int64_t idI, std::int64_t idJ) const
{
  const Pair key{std::min(idI, idJ), std::max(idI, idJ), 0};
  const auto it = std::lower_bound(replaced_.begin(), replaced_.end(), key);
  return it != replaced_.end() && !(key < *it) ? it->weight : 0;
}

} // namespace vp
