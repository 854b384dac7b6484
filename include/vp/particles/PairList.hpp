#pragma once
// Verlet neighbour list of particle pairs (owned x owned once, owned x ghost once), built from
// CellBuckets with a skin and kept until some particle has moved half the skin. Each pair is
// stored in canonical orientation (first = lower global id) with its contact coefficients, its
// tangential spring and its departure state, and the list is sorted by (first id, second id).
// Scattering pair forces in list order then adds to every particle its partners' contributions in
// ascending partner id: the partners below its id come first (pairs led by them), then those above
// (pairs it leads).
// That order does not depend on the decomposition, so the sums are bitwise rank-independent.
#include "vp/interactions/ContactModel.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vp {

struct PairList {
  std::vector<std::uint32_t> first, second;   // local indices, id[first] < id[second]
  std::vector<std::uint32_t> law;              // index into `laws` (pairs of equal m* share one)
  std::vector<ContactCoefficients> laws;
  std::vector<Vec3> spring;                    // tangential spring (canonical orientation)
  std::vector<std::uint8_t> touching;          // in contact at the last force evaluation
  std::vector<std::uint8_t> departure;         // PairDeparture bits (-contact_hydro_departure)

  std::size_t size() const { return first.size(); }

  // Pairs closer than (a_i + a_j)(1 + roughness) + lubricationGap + skin; springs and departure
  // states taken from the owned members' ContactHistory (filled by the caller before, cleared after).
  void build(const ParticleStore& s, const CellBuckets& buckets, double skin, const ContactLaw& law,
             double lubricationGap);
  // Copies the non-zero springs and departure states into the ContactHistory of the owned members.
  void exportHistory(ParticleStore& s) const;

private:
  std::unordered_map<double, std::uint32_t> lawOfMass_;
};

} // namespace vp
