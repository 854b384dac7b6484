#include "vp/particles/PairList.hpp"
#include <algorithm>

namespace vp {

namespace {

struct Candidate {
  std::int64_t idFirst, idSecond;
  std::uint32_t first, second;
};

bool isZero(const Vec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

} // namespace

void PairList::build(const ParticleStore& s, const CellBuckets& buckets, double skin, const ContactLaw& contactLaw,
                     double lubricationGap)
{
  std::vector<Candidate> c;
  c.reserve(first.size() + first.size() / 4 + 16);
  const double rough = contactLaw.roughness();
  buckets.forEachCandidate(s.nOwned, [&](std::size_t i, std::size_t j) {
    const double range = (s.bound[i] + s.bound[j]) * (1 + rough) + lubricationGap + skin;
    const Vec3 d = s.x[i] - s.x[j];
    if (dot(d, d) >= range * range) return;
    // Two fixed spheres interact only through lubrication of prescribed relative motion (resistance
    // studies); moving together (a rough wall's), not at all.
    if (s.invMass[i] + s.invMass[j] == 0 && norm(s.v[i] - s.v[j]) + norm(s.w[i]) + norm(s.w[j]) == 0) return;
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
  law.resize(n);
  spring.resize(n);
  touching.assign(n, 0);
  departure.assign(n, 0);
  laws.clear();
  lawOfMass_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t a = c[k].first, b = c[k].second;
    first[k] = a;
    second[k] = b;
    const double meff = 1 / (s.invMass[a] + s.invMass[b]);
    auto found = lawOfMass_.find(meff);
    if (found == lawOfMass_.end()) {
      found = lawOfMass_.emplace(meff, static_cast<std::uint32_t>(laws.size())).first;
      laws.push_back(contactLaw.coefficients(meff, false));
    }
    law[k] = found->second;
    const std::size_t owner = a < s.nOwned ? a : b;
    const ContactSpring* h = findContact(s.history[owner], s.id[owner == a ? b : a]);
    spring[k] = h ? h->spring : Vec3{};
    touching[k] = h && !isZero(h->spring);
    departure[k] = h ? h->departure : 0;
  }
}

void PairList::exportHistory(ParticleStore& s) const
{
  for (std::size_t k = 0; k < size(); ++k) {
    const Vec3& sp = spring[k];
    if (isZero(sp) && !departure[k]) continue;
    if (first[k] < s.nOwned) s.history[first[k]].push_back({s.id[second[k]], sp, departure[k]});
    if (second[k] < s.nOwned) s.history[second[k]].push_back({s.id[first[k]], sp, departure[k]});
  }
}

} // namespace vp
