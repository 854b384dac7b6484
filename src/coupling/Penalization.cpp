#include "vp/coupling/Penalization.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <algorithm>
#include <cmath>
#include <petscsys.h>

namespace vp {

PenalizationConfig PenalizationConfig::read()
{
  PenalizationConfig c;
  OptionGroup o("Volume penalization of the particles");
  c.mask = static_cast<Mask>(o.choice("-penalization_mask", {"smooth", "sharp"}, 0, "Mask of a sphere on the faces"));
  c.lambda = o.real("-penalization_lambda", c.lambda,
                    "Penalization coefficient lambda (1/s); 0: max(400 nu / h^2, 20 / dt_0.5), a penetration length of at most h/20 "
                    "and the fluid inside a particle following it within 1/20 of dt_0.5, the step at CFL 0.5 of the "
                    "fastest motion so far (fluid, particles, walls, gravity), not of the step taken: results converge in "
                    "dt (docs/coupling.md)");
  c.width = o.real("-penalization_width", c.width, "Width of the smooth mask (cells)");
  c.weightedProjection = o.choice("-penalization_projection", {"plain", "weighted"}, 0,
                                  "Pressure projection of a penalized step: plain (the constant-coefficient Poisson equation, any "
                                  "pressure solver) or weighted (div(grad psi / (1 + chi lambda dt)): the solid resists the "
                                  "correction as it resists the flow, so the pressure in a closing gap builds within the step; an "
                                  "iterative pressure solver, the operator rebuilt every step: -pressure_pc_type pfmg sets up cheaply; "
                                  "docs/coupling.md)") == 1;
  return c;
}

void PenalizationConfig::validate() const
{
  if (!(lambda >= 0)) failOption("-penalization_lambda", "must be >= 0 (0: from the grid), got " + formatNumber(lambda));
  if (!(width > 0 && width <= 4)) failOption("-penalization_width", "must be in (0, 4] cells, got " + formatNumber(width));
}

Penalization::Penalization(const Grid& grid, const PenalizationConfig& cfg, double rho, double nu)
  : grid_(grid), cfg_(cfg), rho_(rho)
{
  const double h = std::min({grid.h(0), grid.h(1), grid.h(2)});
  gridLambda_ = 400 * nu / (h * h);
  support_ = cfg.mask == PenalizationConfig::Mask::Smooth ? 0.5 * cfg.width * h : 0;
  VP_CALL(DMCreateGlobalVector(grid.faceDM(), &chi_));
  VP_CALL(DMCreateGlobalVector(grid.faceDM(), &us_));
  VP_CALL(DMCreateGlobalVector(grid.faceDM(), &theta_));
  VP_CALL(DMCreateGlobalVector(grid.faceDM(), &thetaUs_));
  VP_CALL(PetscObjectSetName((PetscObject)chi_, "chi"));
}

Penalization::~Penalization()
{
  VecDestroy(&thetaUs_);
  VecDestroy(&theta_);
  VecDestroy(&us_);
  VecDestroy(&chi_);
}

void Penalization::build(const ParticleStore& s, double dt, double lambdaFloor)
{
  const Grid& g = grid_;
  VP_CALL(VecSet(chi_, 0));
  VP_CALL(VecSet(us_, 0));
  {
    FaceArray chiA(g.faceDM(), chi_), usA(g.faceDM(), us_);
    PetscScalar ****chi = chiA.a, ****us = usA.a;
    const PetscInt nx = g.end(0) - g.start(0), ny = g.end(1) - g.start(1);
    owner_.assign(3 * nx * ny * (g.end(2) - g.start(2)), -1);
    const double eps = support_;
    for (std::size_t p = 0; p < s.size(); ++p) {
      const Vec3 X = s.x[p];
      const double a = s.radius[p], reach = a + eps;
      for (int c = 0; c < 3; ++c) {
        // Owned faces of component c within reach of the centre (face c sits at index i along c).
        PetscInt lo[3], hi[3];
        for (int d = 0; d < 3; ++d) {
          const double off = d == c ? 0 : 0.5;
          lo[d] = std::max<PetscInt>(g.start(d), PetscInt(std::ceil((X[d] - reach - g.lo(d)) / g.h(d) - off)));
          hi[d] = std::min<PetscInt>(g.end(d), PetscInt(std::floor((X[d] + reach - g.lo(d)) / g.h(d) - off)) + 1);
        }
        // Faces of the bounding box beyond the reach are skipped by their squared distance first
        // (about half of the box: no square root for them).
        const double reach2 = reach * reach;
        auto coord = [&](int d, PetscInt q) { return d == c ? g.faceCoord(d, q) : g.cellCentre(d, q); };
        for (PetscInt k = lo[2]; k < hi[2]; ++k) {
          const double dz = coord(2, k) - X[2], dz2 = dz * dz;
          for (PetscInt j = lo[1]; j < hi[1]; ++j) {
            const double dy = coord(1, j) - X[1], dyz2 = dz2 + dy * dy;
            if (dyz2 > reach2) continue;
            for (PetscInt i = lo[0]; i < hi[0]; ++i) {
              const Vec3 x{coord(0, i), coord(1, j), coord(2, k)};
              const Vec3 r = x - X;
              if (r[0] * r[0] + dyz2 > reach2) continue;
              const double phi = a - norm(r);  // > 0 inside
              double value;
              if (eps == 0) value = phi > 0 ? 1 : 0;
              else if (phi <= -eps) value = 0;
              else if (phi >= eps) value = 1;
              else value = 0.5 * (1 + phi / eps + std::sin(M_PI * phi / eps) / M_PI);
              if (value <= chi[k][j][i][c]) continue;
              chi[k][j][i][c] = value;
              us[k][j][i][c] = (s.v[p] + cross(s.w[p], r))[c];
              owner_[3 * (((k - g.start(2)) * ny + (j - g.start(1))) * nx + (i - g.start(0))) + c] = static_cast<int>(p);
            }
          }
        }
      }
    }
  }
  VP_CALL(VecCopy(chi_, theta_));
  // From the grid, lambda also holds the fluid inside a particle to its motion within a twentieth of
  // the time the flow takes to cross half a cell (the floor): at a small viscosity 400 nu / h^2 alone
  // left the mask porous and lost most of the added mass. The floor follows the fastest motion so far,
  // not the step taken: a stiffer mask seals a sub-cell gap, and a lambda that grew as the step shrank
  // kept rebounds from converging in the step (docs/coupling.md, Simulation::buildMask).
  stepLambda_ = cfg_.lambda > 0 ? cfg_.lambda : std::max(gridLambda_, lambdaFloor);
  VP_CALL(VecScale(theta_, stepLambda_ * dt));
  {
    // A wall face keeps its boundary value: no penalization there.
    FaceArray tA(g.faceDM(), theta_);
    PetscScalar**** t = tA.a;
    for (int c = 0; c < 3; ++c) {
      if (!g.atLow(c)) continue;
      PetscInt lo[3] = {g.start(0), g.start(1), g.start(2)}, hi[3] = {g.end(0), g.end(1), g.end(2)};
      hi[c] = 1;
      for (PetscInt k = lo[2]; k < hi[2]; ++k)
        for (PetscInt j = lo[1]; j < hi[1]; ++j)
          for (PetscInt i = lo[0]; i < hi[0]; ++i) t[k][j][i][c] = 0;
    }
  }
  VP_CALL(VecPointwiseMult(thetaUs_, theta_, us_));
}

// Visits every owned, free face covered by a particle: f(i, j, k, c, p, r, chi), r = face - centre.
template <class F>
void Penalization::forCovered(const ParticleStore& s, F&& f) const
{
  const Grid& g = grid_;
  FaceArray chiA(g.faceDM(), chi_, true);
  PetscScalar**** chi = chiA.a;
  const PetscInt nx = g.end(0) - g.start(0), ny = g.end(1) - g.start(1);
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) {
        const PetscInt q[3] = {i, j, k};
        for (int c = 0; c < 3; ++c) {
          const int p = owner_[3 * (((k - g.start(2)) * ny + (j - g.start(1))) * nx + (i - g.start(0))) + c];
          if (p < 0 || isFixedFace(g, c, q[c])) continue;
          Vec3 x{g.cellCentre(0, i), g.cellCentre(1, j), g.cellCentre(2, k)};
          x[c] = g.faceCoord(c, q[c]);
          f(i, j, k, c, p, x - s.x[p], chi[k][j][i][c]);
        }
      }
}

void Penalization::forces(const ParticleStore& s, Vec uStar, std::vector<double>& sums) const
{
  sums.assign(kHydroSums * s.size(), 0.0);
  const double dV = grid_.cellVolume();
  FaceArray aA(grid_.faceDM(), uStar, true), usA(grid_.faceDM(), us_, true);
  PetscScalar ****a = aA.a, ****us = usA.a;
  forCovered(s, [&](PetscInt i, PetscInt j, PetscInt k, int c, int p, const Vec3& r, double chi) {
    // The particle receives minus the penalization force on the fluid, rho chi lambda (u_s - u*).
    Vec3 f;
    f[c] = rho_ * chi * stepLambda_ * (a[k][j][i][c] - us[k][j][i][c]) * dV;
    const Vec3 t = cross(r, f);
    double* sum = &sums[kHydroSums * p];
    for (int m = 0; m < 3; ++m) {
      sum[m] += f[m];
      sum[3 + m] += t[m];
    }
  });
}

void Penalization::addFluidMomentum(const ParticleStore& s, Vec u, std::vector<double>& sums) const
{
  const double dV = grid_.cellVolume();
  FaceArray aA(grid_.faceDM(), u, true);
  PetscScalar**** a = aA.a;
  forCovered(s, [&](PetscInt i, PetscInt j, PetscInt k, int c, int p, const Vec3& r, double chi) {
    Vec3 momentum;
    momentum[c] = rho_ * chi * a[k][j][i][c] * dV;
    const Vec3 moment = cross(r, momentum);
    double* sum = &sums[kHydroSums * p];
    for (int m = 0; m < 3; ++m) {
      sum[6 + m] += momentum[m];
      sum[9 + m] += moment[m];
    }
  });
}

} // namespace vp
