#pragma once
// Hydrodynamic force and torque on each particle from the penalization (momentum exchange with
// the internal-fluid correction, Kempe & Froehlich 2012 / Uhlmann 2005):
//   F_hyd = -rho sum_faces (u^{n+1} - u~) dV / dt + d/dt (rho sum_faces chi u dV) - rho V g
//   T_hyd = the same moments about the centre.
// The penalization sum is the force the solid exerts on the fluid, reversed; the second term is
// the rate of change of the momentum of the fluid inside the particle, taken from the field at two
// steps (not from the particle's acceleration), which keeps density ratios near 1 stable; the
// last term is buoyancy, since the fluid's pressure excludes the hydrostatic part.
#include "vp/core/Vec3.hpp"
#include "vp/particles/Exchange.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <vector>

namespace vp {

// sums: kHydroSums per particle from Penalization::forces and addFluidMomentum (partial on every rank that holds part
// of a sphere); reduced to the owners here. Sets fhyd, thyd of the owned particles and remembers
// their fluid momentum. dt = 0: initial state, only the fluid momentum is recorded. Collective.
void hydroForces(ParticleStore& s, ParticleExchange& exchange, std::vector<double>& sums, double dt, double rho,
                 const Vec3& gravity);

} // namespace vp
