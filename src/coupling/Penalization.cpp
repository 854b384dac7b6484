#include "vp/coupling/Penalization.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/core/VecValues.hpp"
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
  for (Vec v : {chi_, us_, theta_, thetaUs_}) VP_CALL(VecSet(v, 0));
}

Penalization::~Penalization()
{
  VecDestroy(&thetaUs_);
  VecDestroy(&theta_);
  VecDestroy(&us_);
  VecDestroy(&chi_);
}

namespace {

// (i, j, k) and component c of the faces of a rank's owned arrays (3 per cell), visited in
// increasing order: integer divisions only when the grid row changes.
class FaceWalker {
public:
  explicit FaceWalker(const Grid& g)
    : nx_(g.end(0) - g.start(0)), ny_(g.end(1) - g.start(1)), i0_(g.start(0)), j0_(g.start(1)), k0_(g.start(2)), rowStart_(-2 * nx_)
  {
  }
  struct Face {
    PetscInt index[3];
    int c;
  };
  Face operator()(PetscInt f)
  {
    const PetscInt cell = f / 3;
    if (cell < rowStart_ || cell >= rowStart_ + nx_) {
      const PetscInt row = cell / nx_;
      rowStart_ = row * nx_;
      j_ = row % ny_ + j0_;
      k_ = row / ny_ + k0_;
    }
    return {{cell - rowStart_ + i0_, j_, k_}, static_cast<int>(f - 3 * cell)};
  }

private:
  PetscInt nx_, ny_, i0_, j0_, k0_, rowStart_, j_ = 0, k_ = 0;  // rowStart_: no row yet
};

// Depth of the point r (from the centre, space frame) inside a non-sphere's surface, > 0 inside;
// exact within eps of the surface, and beyond it only its sign and that it exceeds eps matter. The
// point lies on the surface scaled by 1 + G (G the level below): its distance from the surface is
// between |G| times the smallest and the largest semi-axis, which settles most points without the
// iterative distance.
double depth(const Shape& shape, const Quaternion& q, const Vec3& r, double eps)
{
  const Vec3 b = toBody(q, r);
  const double a = shape.a, c = shape.c();
  const double G = std::sqrt((b.x * b.x + b.y * b.y) / (a * a) + b.z * b.z / (c * c)) - 1;
  const double bound = std::fabs(G) * shape.smallestSemiAxis();
  if (bound >= eps) return G > 0 ? -bound : bound;
  return -shape.distance(b);
}

} // namespace

void Penalization::build(const ParticleStore& s, double dt, double lambdaFloor)
{
  const Grid& g = grid_;
  const PetscInt nx = g.end(0) - g.start(0), ny = g.end(1) - g.start(1), nz = g.end(2) - g.start(2);
  // Index of an owned face in the local arrays (and owner_): the faceDM's natural local order.
  auto at = [&](PetscInt i, PetscInt j, PetscInt k, int c) {
    return 3 * (((k - g.start(2)) * ny + (j - g.start(1))) * nx + (i - g.start(0))) + c;
  };
  WriteValues chi(chi_), us(us_), theta(theta_), thetaUs(thetaUs_);
  if (owner_.empty()) owner_.assign(3 * nx * ny * nz, -1);
  // Only the faces the last build covered are non-zero: no sweep over the grid.
  for (const PetscInt f : covered_) {
    chi[f] = us[f] = theta[f] = thetaUs[f] = 0;
    owner_[f] = -1;
  }
  const double eps = support_;
  // Particles in the order of their centres' cells (z, then y, then x): a neighbour's faces are then
  // still in cache. A face shared at equal chi goes to the smaller id, whatever the order.
  std::vector<std::pair<double, std::size_t>> keys(s.size());
  for (std::size_t p = 0; p < s.size(); ++p) {
    double key = 0;
    for (int d = 2; d >= 0; --d) key = key * (g.n(d) + 2) + std::floor((s.x[p][d] - g.lo(d)) / g.h(d));
    keys[p] = {key, p};
  }
  std::sort(keys.begin(), keys.end());
  for (const auto& [key, p] : keys) {
    const Vec3 X = s.x[p];
    const Shape shape = s.shape(p);
    const bool round = shape.sphere();
    const double a = s.bound[p], reach = a + eps, reach2 = reach * reach;
    // Owned faces of component c within reach of the centre, box[c] (face c sits at index i along
    // c); the three components are visited together, cell by cell, as they lie in memory.
    PetscInt lo[3][3], hi[3][3], ulo[3], uhi[3];
    for (int d = 0; d < 3; ++d) ulo[d] = g.end(d), uhi[d] = g.start(d);
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) {
        const double off = d == c ? 0 : 0.5;
        lo[c][d] = std::max<PetscInt>(g.start(d), PetscInt(std::ceil((X[d] - reach - g.lo(d)) / g.h(d) - off)));
        hi[c][d] = std::min<PetscInt>(g.end(d), PetscInt(std::floor((X[d] + reach - g.lo(d)) / g.h(d) - off)) + 1);
        ulo[d] = std::min(ulo[d], lo[c][d]);
        uhi[d] = std::max(uhi[d], hi[c][d]);
      }
    auto coord = [&](int c, int d, PetscInt q) { return d == c ? g.faceCoord(d, q) : g.cellCentre(d, q); };
    for (PetscInt k = ulo[2]; k < uhi[2]; ++k)
      for (PetscInt j = ulo[1]; j < uhi[1]; ++j) {
        // Rows beyond the reach are skipped by their squared distance first (no square root).
        double dyz2[3];
        bool row[3], any = false;
        for (int c = 0; c < 3; ++c) {
          row[c] = k >= lo[c][2] && k < hi[c][2] && j >= lo[c][1] && j < hi[c][1];
          if (!row[c]) continue;
          const double dz = coord(c, 2, k) - X[2], dy = coord(c, 1, j) - X[1];
          dyz2[c] = dz * dz + dy * dy;
          row[c] = dyz2[c] <= reach2;
          any = any || row[c];
        }
        if (!any) continue;
        for (PetscInt i = ulo[0]; i < uhi[0]; ++i)
          for (int c = 0; c < 3; ++c) {
            if (!row[c] || i < lo[c][0] || i >= hi[c][0]) continue;
            const Vec3 r = Vec3{coord(c, 0, i), coord(c, 1, j), coord(c, 2, k)} - X;
            if (r[0] * r[0] + dyz2[c] > reach2) continue;
            const double phi = round ? a - norm(r) : depth(shape, s.q[p], r, eps);  // > 0 inside
            double value;
            if (eps == 0) value = phi > 0 ? 1 : 0;
            else if (phi <= -eps) value = 0;
            else if (phi >= eps) value = 1;
            else value = 0.5 * (1 + phi / eps + std::sin(M_PI * phi / eps) / M_PI);
            const PetscInt f = at(i, j, k, c);
            if (value <= 0 || value < chi[f] || (value == chi[f] && s.id[owner_[f]] < s.id[p])) continue;
            chi[f] = value;
            us[f] = (s.v[p] + cross(s.w[p], r))[c];
            owner_[f] = static_cast<int>(p);
          }
      }
  }
  // The covered faces in the arrays' order (the force sums add in that order on every rank count).
  covered_.clear();
  for (std::size_t f = 0; f < owner_.size(); ++f)
    if (owner_[f] >= 0) covered_.push_back(static_cast<PetscInt>(f));
  // From the grid, lambda also holds the fluid inside a particle to its motion within a twentieth of
  // the time the flow takes to cross half a cell (the floor): at a small viscosity 400 nu / h^2 alone
  // left the mask porous and lost most of the added mass. The floor follows the fastest motion so far,
  // not the step taken: a stiffer mask seals a sub-cell gap, and a lambda that grew as the step shrank
  // kept rebounds from converging in the step (docs/coupling.md, Simulation::buildMask).
  stepLambda_ = cfg_.lambda > 0 ? cfg_.lambda : std::max(gridLambda_, lambdaFloor);
  const double scale = stepLambda_ * dt;
  FaceWalker face(g);
  for (const PetscInt f : covered_) {
    const FaceWalker::Face q = face(f);
    // A wall face keeps its boundary value: no penalization there.
    theta[f] = isFixedFace(g, q.c, q.index[q.c]) ? 0 : chi[f] * scale;
    thetaUs[f] = theta[f] * us[f];
  }
}

// Visits every owned, free face covered by a particle: f(index in the owned arrays, component c,
// particle p, r = face - centre, chi).
template <class F>
void Penalization::forCovered(const ParticleStore& s, F&& f) const
{
  const Grid& g = grid_;
  ReadValues chi(chi_);
  FaceWalker face(g);
  for (const PetscInt at : covered_) {
    const FaceWalker::Face q = face(at);
    if (isFixedFace(g, q.c, q.index[q.c])) continue;
    const int p = owner_[at];
    Vec3 x{g.cellCentre(0, q.index[0]), g.cellCentre(1, q.index[1]), g.cellCentre(2, q.index[2])};
    x[q.c] = g.faceCoord(q.c, q.index[q.c]);
    f(at, q.c, p, x - s.x[p], chi[at]);
  }
}

void Penalization::forces(const ParticleStore& s, Vec uStar, std::vector<double>& sums, const LubricationPatches* patches)
{
  sums.assign(kHydroSums * s.size(), 0.0);
  const double dV = grid_.cellVolume();
  ReadValues a(uStar), us(us_);
  forCovered(s, [&](PetscInt at, int c, int p, const Vec3& r, double chi) {
    // The particle receives minus the penalization force on the fluid, rho chi lambda (u_s - u*).
    Vec3 f;
    f[c] = rho_ * chi * stepLambda_ * (a[at] - us[at]) * dV;
    const Vec3 t = cross(r, f);
    // In a gap patch the analytic squeeze stands for (its weight's fraction of) the normal force;
    // its moment (the pressure of the tangential motions) stays resolved.
    if (const LubricationPatches::Patch* q = patches ? patches->patchAt(p, r) : nullptr)
      f -= (q->weight * f[c] * q->n[c]) * q->n;
    double* sum = &sums[kHydroSums * p];
    for (int m = 0; m < 3; ++m) {
      sum[m] += f[m];
      sum[3 + m] += t[m];
    }
    if (stresslets_ && s.x[p].z >= stressletLo_ && s.x[p].z <= stressletHi_) {
      const SymTensor m = symmetricProduct(r, f);
      for (int k = 0; k < 6; ++k) stressletSum_[k] += m[k];
    }
  });
  stressletSteps_ += stresslets_;
}

void Penalization::enableStresslets(double zlo, double zhi)
{
  stresslets_ = true;
  stressletLo_ = zlo;
  stressletHi_ = zhi;
}

SymTensor Penalization::takeStresslets()
{
  SymTensor m = stressletSum_;
  for (double& v : m) v /= std::max<long>(stressletSteps_, 1);
  stressletSum_ = {};
  stressletSteps_ = 0;
  return m;
}

void Penalization::addFluidMomentum(const ParticleStore& s, Vec u, std::vector<double>& sums) const
{
  const double dV = grid_.cellVolume();
  ReadValues a(u);
  forCovered(s, [&](PetscInt at, int c, int p, const Vec3& r, double chi) {
    Vec3 momentum;
    momentum[c] = rho_ * chi * a[at] * dV;
    const Vec3 moment = cross(r, momentum);
    double* sum = &sums[kHydroSums * p];
    for (int m = 0; m < 3; ++m) {
      sum[6 + m] += momentum[m];
      sum[9 + m] += moment[m];
    }
  });
}

} // namespace vp
