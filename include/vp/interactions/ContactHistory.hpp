#pragma once
// History of the contacts of one particle, keyed by partner id: the tangential spring and the pair's
// departure state (-contact_hydro_departure: an impact, or leaving after one). It lives with the
// owned particle while the particle migrates; between neighbour-list rebuilds it is held per pair by
// the PairList. Pair springs are stored in the pair's canonical orientation (normal from the
// higher-id to the lower-id sphere), so both owners of a split pair keep the same value.
#include "vp/core/Vec3.hpp"
#include <cstdint>
#include <vector>

namespace vp {

struct ContactSpring {
  std::int64_t partner;
  Vec3 spring;
  std::uint8_t departure = 0;  // PairDeparture bits
};

// A pair's departure state: its contact was an impact (pressed beyond twice the buoyant-weight
// overlap), or its spheres are leaving each other after one, closer than the departure gap.
enum PairDeparture : std::uint8_t { kPairImpact = 1, kPairLeaving = 2 };

using ContactHistory = std::vector<ContactSpring>;

inline const ContactSpring* findContact(const ContactHistory& h, std::int64_t partner)
{
  for (const ContactSpring& c : h)
    if (c.partner == partner) return &c;
  return nullptr;
}

} // namespace vp
