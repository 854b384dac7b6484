#pragma once
// Analytic flows used as initial conditions and as exact solutions in tests:
//   taylor_green: u = U cos(kx x) sin(ky y), v = -U (kx/ky) sin(kx x) cos(ky y), decaying as
//                 exp(-nu (kx^2 + ky^2) t) (periodic x, y; k = 2 pi / L),
//   abc:          the Arnold-Beltrami-Childress flow with A = B = C = U, an exact 3-D solution in a
//                 periodic cube (the convection is a pure gradient), decaying as exp(-nu k^2 t),
//   poiseuille:   u = f_x / (2 nu) (y - y_lo)(y_hi - y), steady, between walls in y,
//   couette:      the linear profile between the z walls' velocities, steady (a shear cell).
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"

namespace vp {

class AnalyticFlow {
public:
  explicit AnalyticFlow(const Config& cfg);
  double velocity(int c, const Vec3& x, double t) const;
  double pressure(const Vec3& x, double t) const;  // dynamic pressure (Pa)

private:
  InitFlow kind_;
  double U_, nu_, rho_, fx_;
  Vec3 wallLo_, wallHi_;  // z walls' velocities (couette)
  double lo_[3], hi_[3], k_[3];
};

// Samples the flow at the owned faces (u, faceDM global vector) and cells (p, cellDM global).
void sampleVelocity(const Grid& grid, const AnalyticFlow& flow, double t, Vec u);
void samplePressure(const Grid& grid, const AnalyticFlow& flow, double t, Vec p);

} // namespace vp
