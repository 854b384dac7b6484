#pragma once
// Verlet neighbour list of particle pairs (owned x owned once, owned x ghost once), built from
// CellBuckets with a skin and kept until some particle has moved half the skin. Each pair is
// stored in canonical orientation (first = lower global id) with its contact coefficients, its
// tangential spring and, after a force evaluation, its force on the first sphere. The incidence
// lists give each owned particle its pairs sorted by partner id, so a particle's force is summed
// in the same order on any number of ranks.
#include "vp/interactions/ContactModel.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <cstdint>
#include <vector>

namespace vp {

struct PairList {
  std::vector<std::uint32_t> first, second;   // local indices, id[first] < id[second]
  std::vector<ContactCoefficients> coef;
  std::vector<Vec3> spring;                    // tangential spring (canonical orientation)
  std::vector<Vec3> force;                     // on `first`; `second` gets -force
  std::vector<Vec3> lever;                     // (r / (a_i + a_j)) n x F_t: torque on either sphere is -radius * lever
  std::vector<std::uint8_t> active;            // in contact at the last force evaluation
  std::vector<std::uint32_t> incStart;         // per owned particle, into incPair / incSign
  std::vector<std::uint32_t> incPair;
  std::vector<double> incSign;                 // +1: particle is `first`, -1: `second`

  std::size_t size() const { return first.size(); }

  // Pairs closer than (a_i + a_j)(1 + roughness) + skin; springs taken from the owned members'
  // ContactHistory (which the caller fills before and clears after).
  void build(const ParticleStore& s, const CellBuckets& buckets, double skin, const ContactLaw& law);
  // Moves the non-zero springs into the ContactHistory of the owned members.
  void exportHistory(ParticleStore& s) const;
};

} // namespace vp
