#include "vp/interactions/Blcm.hpp"

namespace vp {

PairForce blcmForce(const PairState& s)
{
  const double R = s.reducedRadius();
  PairForce f;
  f.forceI = (6 * M_PI * s.viscosity * R * R * s.gapRate() / s.gap) * s.normal;
  return f;
}

} // namespace vp
