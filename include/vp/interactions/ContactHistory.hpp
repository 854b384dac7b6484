#pragma once
// Tangential-spring history of the contacts of one particle, keyed by partner id. It lives with the
// owned particle while the particle migrates; between neighbour-list rebuilds the springs are held
// per pair by the PairList. Pair springs are stored in the pair's canonical orientation (normal from
// the higher-id to the lower-id sphere), so both owners of a split pair keep the same value.
#include "vp/core/Vec3.hpp"
#include <cstdint>
#include <vector>

namespace vp {

struct ContactSpring {
  std::int64_t partner;
  Vec3 spring;
};

using ContactHistory = std::vector<ContactSpring>;

inline const Vec3* findSpring(const ContactHistory& h, std::int64_t partner)
{
  for (const ContactSpring& c : h)
    if (c.partner == partner) return &c.spring;
  return nullptr;
}

} // namespace vp
