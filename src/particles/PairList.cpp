#include "vp/particles/PairList.hpp"
#include <algorithm>

namespace vp {

namespace {

struct Candidate {
  std::int64_t idFirst, idSecond;
  std::uint32_t first, second;
};

} // namespace

void PairList::build(const ParticleStore& s, const CellBuckets& buckets, double skin, const ContactLaw& law)
{
  std::vector<Candidate> c;
  c.reserve(first.size() + first.size() / 4 + 16);
  const double rough = law.roughness();
  buckets.forEachCandidate(s.nOwned, [&](std::size_t i, std::size_t j) {
    const double range = (s.radius[i] + s.radius[j]) * (1 + rough) + skin;
    const Vec3 d = s.x[i] - s.x[j];
    if (dot(d, d) >= range * range) return;
    if (s.invMass[i] + s.invMass[j] == 0) return;  // two fixed spheres never interact
    const bool swap = s.id[j] < s.id[i];
    const auto a = static_cast<std::uint32_t>(swap ? j : i), b = static_cast<std::uint32_t>(swap ? i : j);
    c.push_back({s.id[a], s.id[b], a, b});
  });
  std::sort(c.begin(), c.end(), [](const Candidate& p, const Candidate& q) {
    return p.idFirst < q.idFirst || (p.idFirst == q.idFirst && p.idSecond < q.idSecond);
  });
  const std::size_t n = c.size();
  first.resize(n);
  second.resize(n);
  coef.resize(n);
  spring.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t a = c[k].first, b = c[k].second;
    first[k] = a;
    second[k] = b;
    coef[k] = law.coefficients(1 / (s.invMass[a] + s.invMass[b]), false);
    const std::size_t owner = a < s.nOwned ? a : b;
    const Vec3* h = findSpring(s.history[owner], s.id[owner == a ? b : a]);
    spring[k] = h ? *h : Vec3{};
  }
}

void PairList::exportHistory(ParticleStore& s) const
{
  for (std::size_t k = 0; k < size(); ++k) {
    const Vec3& sp = spring[k];
    if (sp.x == 0 && sp.y == 0 && sp.z == 0) continue;
    if (first[k] < s.nOwned) s.history[first[k]].push_back({s.id[second[k]], sp});
    if (second[k] < s.nOwned) s.history[second[k]].push_back({s.id[first[k]], sp});
  }
}

} // namespace vp
