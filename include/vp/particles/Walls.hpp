#pragma once
// The plane walls that bound the particles: every non-periodic face of the domain. Face f = 2*axis
// + side; the normal points into the domain; a 'velocity' face moves with its prescribed velocity.
#include "vp/core/Config.hpp"
#include <array>

namespace vp {

struct Wall {
  bool active = false;
  int axis = 0;
  double position = 0;
  double normalSign = 1;   // +1 on the low face, -1 on the high face
  bool slip = false;       // free-slip face (lubrication: docs/lubrication.md)
  Vec3 velocity;

  // Distance from a point to the wall plane, positive inside the domain.
  double distance(const Vec3& x) const { return normalSign * (x[axis] - position); }
  Vec3 normal() const
  {
    Vec3 n;
    n[axis] = normalSign;
    return n;
  }
};

inline std::array<Wall, 6> domainWalls(const Config& c)
{
  std::array<Wall, 6> w;
  for (int f = 0; f < 6; ++f) {
    const int d = f / 2;
    w[f].active = !c.bc.periodic(d);
    w[f].axis = d;
    w[f].position = (f % 2 == 0) ? c.grid.lo[d] : c.grid.hi[d];
    w[f].normalSign = (f % 2 == 0) ? 1 : -1;
    w[f].slip = c.bc.type[f] == BcType::Slip;
    if (c.bc.type[f] == BcType::Velocity) w[f].velocity = c.bc.velocity[f];
  }
  return w;
}

} // namespace vp
