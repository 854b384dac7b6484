// The mask build against its definition: chi, u_s, theta and the force sums of Penalization
// (built from the faces the spheres reach, reset only where the last build covered) equal a sweep
// over every owned face that applies the formulas of docs/coupling.md directly, on any number of
// ranks, and a moved sphere leaves nothing behind.
#include "../support/DemFixtures.hpp"
#include "vp/core/Error.hpp"
#include "vp/coupling/Penalization.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace vp;
using namespace vp::test;

namespace {

// chi of sphere p at point x: the smoothed Heaviside over half a cell each side of the surface.
double maskOf(const ParticleStore& s, std::size_t p, const Vec3& x, double e)
{
  const double phi = s.radius[p] - norm(x - s.x[p]);
  if (phi <= -e) return 0;
  if (phi >= e) return 1;
  return 0.5 * (1 + phi / e + std::sin(M_PI * phi / e) / M_PI);
}

// Every owned face against the definition; returns the mismatches, and the force sums of the sweep.
std::string sweep(const Grid& g, const Penalization& pen, const ParticleStore& s, Vec u, double dt, std::vector<double>& sums)
{
  const double lambda = pen.lambda(), scale = lambda * dt;
  const double e = pen.support(), dV = g.cellVolume();
  sums.assign(kHydroSums * s.size(), 0.0);
  FaceArray chiA(g.faceDM(), pen.chi(), true), tA(g.faceDM(), pen.theta(), true), tuA(g.faceDM(), pen.thetaUs(), true),
    uA(g.faceDM(), u, true);
  std::string bad;
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        for (int c = 0; c < 3; ++c) {
          const PetscInt q[3] = {i, j, k};
          Vec3 x{g.cellCentre(0, i), g.cellCentre(1, j), g.cellCentre(2, k)};
          x[c] = g.faceCoord(c, q[c]);
          double best = 0;
          int owner = -1;
          for (std::size_t p = 0; p < s.size(); ++p) {
            const double m = maskOf(s, p, x, e);
            if (m > best || (m == best && m > 0 && s.id[p] < s.id[owner])) best = m, owner = int(p);
          }
          const bool fixed = isFixedFace(g, c, q[c]);
          const double theta = fixed ? 0 : best * scale;
          const double us = owner < 0 ? 0 : (s.v[owner] + cross(s.w[owner], x - s.x[owner]))[c];
          if (chiA.a[k][j][i][c] != best || tA.a[k][j][i][c] != theta || tuA.a[k][j][i][c] != theta * us)
            bad += " face " + std::to_string(i) + "," + std::to_string(j) + "," + std::to_string(k) + "/" + std::to_string(c);
          if (owner < 0 || fixed) continue;
          Vec3 f;
          f[c] = 1000 * best * lambda * (uA.a[k][j][i][c] - us) * dV;  // rho chi lambda (u* - u_s) dV
          const Vec3 t = cross(x - s.x[owner], f);
          for (int m = 0; m < 3; ++m) {
            sums[kHydroSums * owner + m] += f[m];
            sums[kHydroSums * owner + 3 + m] += t[m];
          }
        }
  return bad;
}

} // namespace

TEST_CASE("Penalization: the mask, theta and the force sums equal a sweep over every face, and a moved sphere leaves none",
          "[mpi][coupling]")
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {16, 12, 20});
  Grid grid(comm, c.grid, c.bc);
  PenalizationConfig pc;
  Penalization pen(grid, pc, 1000, 1e-3);
  // Two spheres whose smooth shells overlap (faces shared at different chi), one spinning, one
  // touching the x = 0 wall's fixed faces; every rank lists all (as owned or ghost).
  ParticleStore s;
  s.append(sphere(7, {0.1, 0.5, 0.45}, 0.12, 2000, {0.1, -0.2, 0.3}, {1, 2, -3}));
  s.append(sphere(3, {0.33, 0.52, 0.5}, 0.1, 2000, {-0.4, 0, 0.1}, {0, -2, 1}));
  // A third at the y = 0 wall across the middle height: on 2 and 3 ranks it covers the first grid
  // row (y = 0) of a rank that does not start at z = 0.
  s.append(sphere(5, {0.5, 0.03, 0.5}, 0.09, 2000, {0, 0.1, 0}, {3, 0, 0}));
  s.nOwned = s.size();
  Vec u;
  VP_CALL(DMCreateGlobalVector(grid.faceDM(), &u));
  {
    FaceArray a(grid.faceDM(), u);
    for (PetscInt k = grid.start(2); k < grid.end(2); ++k)
      for (PetscInt j = grid.start(1); j < grid.end(1); ++j)
        for (PetscInt i = grid.start(0); i < grid.end(0); ++i)
          for (int m = 0; m < 3; ++m) a.a[k][j][i][m] = std::sin(0.3 * i + 0.7 * j - 0.2 * k + m);
  }
  const double dt = 1e-3, floor = 5e5;
  for (int round = 0; round < 2; ++round) {
    if (round == 1) s.x[0] = {0.7, 0.4, 0.6};  // moved far: its old faces must be zero again
    pen.build(s, dt, floor);
    std::vector<double> sums, want;
    pen.forces(s, u, sums);
    const std::string bad = sweep(grid, pen, s, u, dt, want);
    INFO("round " << round << ":" << bad.substr(0, 300));
    CHECK(allRanks(comm, bad.empty()));
    std::vector<double> all(sums.size()), allWant(want.size());
    MPI_Allreduce(sums.data(), all.data(), int(sums.size()), MPI_DOUBLE, MPI_SUM, comm);
    MPI_Allreduce(want.data(), allWant.data(), int(want.size()), MPI_DOUBLE, MPI_SUM, comm);
    for (std::size_t n = 0; n < all.size(); ++n)
      if (n % kHydroSums < 6) CHECK(all[n] == Approx(allWant[n]).epsilon(1e-12).margin(1e-300));
    CHECK(std::fabs(all[0]) + std::fabs(all[kHydroSums]) > 0);  // both spheres receive a force
  }
  VecDestroy(&u);
}

TEST_CASE("Penalization: a rotated spheroid's mask has its volume, centre and inertia tensor", "[mpi][coupling][shape]")
{
  // Prolate (aspect 2), its axis along (1, 2, 2) / 3, off the grid's symmetry, d_v / dx = 12.6:
  // the moments of chi over each face component against the spheroid's, turned into space.
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {40, 40, 40});
  Grid grid(comm, c.grid, c.bc);
  Penalization pen(grid, PenalizationConfig{}, 1000, 1e-3);
  ParticleStore s;
  ParticleRecord r = sphere(0, {0.49, 0.52, 0.505}, 0.125, 1000);
  r.aspect.value = 2;
  r.q = alignedWith(Vec3{1, 2, 2} / 3.0);
  s.append(r);
  s.nOwned = 1;
  pen.build(s, 1e-3, 5e5);
  const Shape g = s.shape(0);
  const Vec3 Ib = g.volume() * g.inertiaOverMass();
  Tensor3 body{};
  body[0] = Ib.x, body[4] = Ib.y, body[8] = Ib.z;
  const Tensor3 I = rotatedTensor(body, r.q);  // per unit density
  FaceArray chi(grid.faceDM(), pen.chi(), true);
  const double dV = grid.cellVolume();
  for (int m = 0; m < 3; ++m) {
    double sums[13] = {};  // volume, first moments, second moments (3 x 3)
    for (PetscInt k = grid.start(2); k < grid.end(2); ++k)
      for (PetscInt j = grid.start(1); j < grid.end(1); ++j)
        for (PetscInt i = grid.start(0); i < grid.end(0); ++i) {
          const PetscInt q[3] = {i, j, k};
          Vec3 x{grid.cellCentre(0, i), grid.cellCentre(1, j), grid.cellCentre(2, k)};
          x[m] = grid.faceCoord(m, q[m]);
          const double w = chi.a[k][j][i][m] * dV;
          const Vec3 d = x - r.x;
          sums[0] += w;
          for (int a = 0; a < 3; ++a) sums[1 + a] += w * x[a];
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) sums[4 + 3 * a + b] += w * ((a == b) * dot(d, d) - d[a] * d[b]);
        }
    MPI_Allreduce(MPI_IN_PLACE, sums, 13, MPI_DOUBLE, MPI_SUM, comm);
    INFO("face component " << m);
    CHECK(sums[0] == Approx(g.volume()).epsilon(0.01));
    for (int a = 0; a < 3; ++a) CHECK(sums[1 + a] / sums[0] == Approx(r.x[a]).margin(0.05 * grid.h(0)));  // a twentieth of a cell
    const double scale = I[0] + I[4] + I[8];
    for (int e = 0; e < 9; ++e) CHECK(sums[4 + e] == Approx(I[e]).margin(0.01 * scale));
  }
}
