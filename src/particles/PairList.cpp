#include "vp/particles/PairList.hpp"
#include <algorithm>

namespace vp {

void PairList::build(const ParticleStore& s, const CellBuckets& buckets, double skin, const ContactLaw& law)
{
  first.clear();
  second.clear();
  coef.clear();
  spring.clear();
  const double rough = law.roughness();
  buckets.forEachCandidate(s.nOwned, [&](std::size_t i, std::size_t j) {
    const double range = (s.radius[i] + s.radius[j]) * (1 + rough) + skin;
    const Vec3 d = s.x[i] - s.x[j];
    if (dot(d, d) >= range * range) return;
    const double invSum = s.invMass[i] + s.invMass[j];
    if (invSum == 0) return;  // two fixed spheres never interact
    const bool swap = s.id[j] < s.id[i];
    const std::size_t a = swap ? j : i, b = swap ? i : j;
    first.push_back(static_cast<std::uint32_t>(a));
    second.push_back(static_cast<std::uint32_t>(b));
    coef.push_back(law.coefficients(1 / invSum, false));
    const std::size_t owner = a < s.nOwned ? a : b;
    const Vec3* h = findSpring(s.history[owner], s.id[owner == a ? b : a]);
    spring.push_back(h ? *h : Vec3{});
  });
  force.assign(size(), Vec3{});
  lever.assign(size(), Vec3{});
  active.assign(size(), 0);

  // Incidence of each owned particle, sorted by partner id.
  incStart.assign(s.nOwned + 1, 0);
  for (std::size_t k = 0; k < size(); ++k) {
    if (first[k] < s.nOwned) ++incStart[first[k] + 1];
    if (second[k] < s.nOwned) ++incStart[second[k] + 1];
  }
  for (std::size_t i = 0; i < s.nOwned; ++i) incStart[i + 1] += incStart[i];
  incPair.resize(incStart[s.nOwned]);
  incSign.resize(incStart[s.nOwned]);
  std::vector<std::uint32_t> fill(incStart.begin(), incStart.end() - 1);
  for (std::size_t k = 0; k < size(); ++k) {
    if (first[k] < s.nOwned) incPair[fill[first[k]]++] = static_cast<std::uint32_t>(k);
    if (second[k] < s.nOwned) incPair[fill[second[k]]++] = static_cast<std::uint32_t>(k);
  }
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    auto partner = [&](std::uint32_t k) { return s.id[first[k] == i ? second[k] : first[k]]; };
    std::sort(incPair.begin() + incStart[i], incPair.begin() + incStart[i + 1],
              [&](std::uint32_t p, std::uint32_t q) { return partner(p) < partner(q); });
    for (std::uint32_t e = incStart[i]; e < incStart[i + 1]; ++e) incSign[e] = first[incPair[e]] == i ? 1.0 : -1.0;
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
