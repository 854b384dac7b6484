#include "vp/fluid/AnalyticFlow.hpp"
#include "vp/core/Error.hpp"
#include <cmath>

namespace vp {

AnalyticFlow::AnalyticFlow(const Config& cfg)
  : kind_(cfg.fluid.init), U_(cfg.fluid.initVelocity), nu_(cfg.fluid.nu()), rho_(cfg.fluid.rho),
    fx_(cfg.fluid.bodyForce.x), wallLo_(cfg.bc.velocity[4]), wallHi_(cfg.bc.velocity[5])
{
  for (int d = 0; d < 3; ++d) {
    lo_[d] = cfg.grid.lo[d];
    hi_[d] = cfg.grid.hi[d];
    k_[d] = 2 * M_PI / (hi_[d] - lo_[d]);
  }
}

double AnalyticFlow::velocity(int c, const Vec3& x, double t) const
{
  const double a = k_[0] * (x.x - lo_[0]), b = k_[1] * (x.y - lo_[1]), z = k_[2] * (x.z - lo_[2]);
  switch (kind_) {
  case InitFlow::Rest:
    return 0;
  case InitFlow::TaylorGreen: {
    const double decay = U_ * std::exp(-nu_ * (k_[0] * k_[0] + k_[1] * k_[1]) * t);
    if (c == 0) return decay * std::cos(a) * std::sin(b);
    if (c == 1) return -decay * (k_[0] / k_[1]) * std::sin(a) * std::cos(b);
    return 0;
  }
  case InitFlow::Abc: {
    const double decay = U_ * std::exp(-nu_ * k_[0] * k_[0] * t);
    if (c == 0) return decay * (std::sin(z) + std::cos(b));
    if (c == 1) return decay * (std::sin(a) + std::cos(z));
    return decay * (std::sin(b) + std::cos(a));
  }
  case InitFlow::Poiseuille:
    return c == 0 ? fx_ / (2 * nu_) * (x.y - lo_[1]) * (hi_[1] - x.y) : 0;
  case InitFlow::Couette:
    return wallLo_[c] + (wallHi_[c] - wallLo_[c]) * (x.z - lo_[2]) / (hi_[2] - lo_[2]);
  }
  return 0;
}

double AnalyticFlow::pressure(const Vec3& x, double t) const
{
  const double a = k_[0] * (x.x - lo_[0]), b = k_[1] * (x.y - lo_[1]);
  switch (kind_) {
  case InitFlow::TaylorGreen: {
    const double r = k_[0] / k_[1];
    const double decay = std::exp(-2 * nu_ * (k_[0] * k_[0] + k_[1] * k_[1]) * t);
    return -0.25 * rho_ * U_ * U_ * (std::cos(2 * a) + r * r * std::cos(2 * b)) * decay;
  }
  case InitFlow::Abc: {
    double u2 = 0;
    for (int c = 0; c < 3; ++c) u2 += std::pow(velocity(c, x, t), 2);
    return -0.5 * rho_ * u2;
  }
  default:
    return 0;
  }
}

void sampleVelocity(const Grid& g, const AnalyticFlow& flow, double t, Vec u)
{
  PetscScalar**** a;
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), u, &a));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) {
        const PetscInt q[3] = {i, j, k};
        for (int c = 0; c < 3; ++c) {
          Vec3 x{g.cellCentre(0, i), g.cellCentre(1, j), g.cellCentre(2, k)};
          x[c] = g.faceCoord(c, q[c]);
          a[k][j][i][c] = flow.velocity(c, x, t);
        }
      }
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), u, &a));
}

void samplePressure(const Grid& g, const AnalyticFlow& flow, double t, Vec p)
{
  PetscScalar*** a;
  VP_CALL(DMDAVecGetArray(g.cellDM(), p, &a));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        a[k][j][i] = flow.pressure({g.cellCentre(0, i), g.cellCentre(1, j), g.cellCentre(2, k)}, t);
  VP_CALL(DMDAVecRestoreArray(g.cellDM(), p, &a));
}

} // namespace vp
