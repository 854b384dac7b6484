// Sphere-sphere lubrication across a rank boundary: the pair is computed on both owners from the
// same data, so the result is bitwise that of one rank, and the pair conserves momentum.
#include "../support/DemFixtures.hpp"
#include <catch2/catch.hpp>

using namespace vp;
using namespace vp::test;

namespace {

// The particles after `steps` DEM steps of dt on comm (every rank gets every particle's state).
std::vector<State> advanced(MPI_Comm comm, const Config& c, const ParticleConfig& pc, const std::vector<ParticleRecord>& p,
                            int steps, double dt)
{
  Grid grid(comm, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), p);
  for (int k = 0; k < steps; ++k) dem.advance(k * dt, dt);
  return gatherState(comm, dem.particles());
}

} // namespace

TEST_CASE("Lubricated head-on approach across ranks: bitwise one-rank result, momentum conserved", "[mpi][particles][lub]")
{
  Config c = boxConfig({0, 0, 0}, {0.04, 0.01, 0.01}, {12, 2, 2});
  c.fluid.mu = 0.05;
  ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 5e-4, LubModel::Blcm, 0.5);
  const double a = 1e-3;
  // Approaching along x and sliding past each other in y, spinning: squeeze plus shear torques.
  const std::vector<ParticleRecord> p = {sphere(1, {0.02 - a * 1.2, 0.005, 0.005}, a, 1000, {0.01, 0.002, 0}, {0, 0, 5}),
                                         sphere(2, {0.02 + a * 1.2, 0.0052, 0.005}, a, 1000, {-0.01, 0, 0})};
  const std::vector<State> parallel = advanced(PETSC_COMM_WORLD, c, pc, p, 5000, 2e-6);
  const std::vector<State> serial = advanced(PETSC_COMM_SELF, c, pc, p, 5000, 2e-6);
  REQUIRE(parallel.size() == 2);
  CHECK(bitwiseEqual(parallel, serial));
  // Equal masses: the velocity sum is conserved.
  const Vec3 sum = parallel[0].v + parallel[1].v;
  CHECK(std::fabs(sum.x) <= 1e-15);
  CHECK(std::fabs(sum.y - 0.002) <= 1e-15);
  // The lubrication drag slowed the approach (no contact: the gap stays above the roughness).
  const double gap = norm(parallel[1].x - parallel[0].x) - 2 * a;
  const double closing = parallel[0].v.x - parallel[1].v.x;
  INFO("gap " << gap / a << " a, closing speed " << closing << " (initially 0.02)");
  CHECK(gap > 1e-3 * a);
  CHECK(closing < 0.5 * 0.02);
}

TEST_CASE("Implicit squeeze among many neighbours across ranks: bitwise one-rank result", "[mpi][particles][lub]")
{
  // A lattice of 4 x 2 x 2 spheres 0.05 a apart with walls 0.05 a away, random velocities, strong
  // lubrication (c dt / m* 2 between spheres, 7 at the walls, at the start): every sphere has several squeezing partners on
  // both sides of a rank boundary, and the Jacobi sweeps must give the same digits on any rank count.
  Config c = boxConfig({0, 0, 0}, {0.0082, 0.0041, 0.0041}, {8, 2, 2});
  c.fluid.mu = 2;
  ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 1e-3, LubModel::Blcm, 0.5);
  pc.lubrication.implicitSqueeze = true;
  const double a = 1e-3, step = 2.05 * a;
  std::vector<ParticleRecord> p;
  std::uint64_t seed = 7;
  auto uniform = [&]() { seed = seed * 6364136223846793005ULL + 1442695040888963407ULL; return double(seed >> 11) * 0x1.0p-53 - 0.5; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i)
        p.push_back(sphere(i + 4 * (j + 2 * k), {1.025 * a + i * step, 1.025 * a + j * step, 1.025 * a + k * step}, a, 1000,
                           {0.01 * uniform(), 0.01 * uniform(), 0.01 * uniform()}));
  const std::vector<State> parallel = advanced(PETSC_COMM_WORLD, c, pc, p, 200, 2e-5);
  const std::vector<State> serial = advanced(PETSC_COMM_SELF, c, pc, p, 200, 2e-5);
  REQUIRE(parallel.size() == 16);
  CHECK(bitwiseEqual(parallel, serial));
}

TEST_CASE("Pair departure across ranks (-contact_hydro_departure, _history): bitwise one-rank result", "[mpi][particles][lub]")
{
  // A coupled run's DEM without its fluid (resolved force zero, no gravity): two spheres collide on a
  // rank boundary and leave each other with the departure; its state lives in both owners' lists,
  // the history force's modes with each sphere.
  Config c = boxConfig({0, 0, 0}, {0.04, 0.01, 0.01}, {40, 4, 4});
  c.fluid.off = false;
  c.fluid.mu = 0.005;  // impact St = rho_p u d / (9 mu) = 139: a rebound
  c.fluid.rho = 935;
  ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 5e-4, LubModel::Blcm, 0.1);
  pc.contact.departureCells = 0.25;  // 0.25 mm; the activation 0.1 a = 0.1 mm
  pc.contact.hydroHistory = true;
  const double a = 1e-3;
  // On the upper boundary of rank 0's block (the middle with one rank): the pair is split on any count.
  double xc = 0.02;
  int size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size > 1) {
    const Grid probe(PETSC_COMM_WORLD, c.grid, c.bc);
    xc = probe.faceCoord(0, probe.end(0));
    MPI_Bcast(&xc, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  }
  const double dt = 2e-6;
  // departed: a sphere was departing with the history force acting; owners: how many ranks owned
  // sphere 2 while it was in its window (modes non-zero: the contact, then the departure).
  auto run = [&](MPI_Comm comm, const std::vector<ParticleRecord>& p, int& departed, int& owners) {
    Grid grid(comm, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc), p);
    int local = 0, owned2 = 0;
    for (int k = 0; k < 3000; ++k) {
      dem.advance(k * dt, dt);
      const ParticleStore& s = dem.particles();
      for (std::size_t i = 0; i < s.nOwned; ++i) {
        const bool inWindow = (s.flags[i] & kPairDeparting) && !s.windowHistory[i].empty() &&
                              BassetKernel::integral(s.windowHistory[i].front().modes).x != 0;
        local = local || inWindow;
        owned2 = owned2 || (s.id[i] == 2 && !s.windowHistory[i].empty() && BassetKernel::integral(s.windowHistory[i].front().modes).x != 0);
      }
    }
    MPI_Allreduce(&local, &departed, 1, MPI_INT, MPI_LOR, comm);
    MPI_Allreduce(&owned2, &owners, 1, MPI_INT, MPI_SUM, comm);
    return gatherState(comm, dem.particles());
  };
  // Head-on on the boundary (the pair split between two owners), then drifting at 0.05 m/s so that
  // sphere 2 crosses the boundary inside its window: its modes and the pair's state migrate with it.
  const std::vector<std::vector<ParticleRecord>> layouts = {
    {sphere(1, {xc - a * 1.2, 0.005, 0.005}, a, 7800, {0.2, 0, 0}), sphere(2, {xc + a * 1.2, 0.005, 0.005}, a, 7800, {-0.2, 0, 0})},
    {sphere(1, {xc - a * 2.25, 0.005, 0.005}, a, 7800, {0.25, 0, 0}), sphere(2, {xc + a * 0.15, 0.005, 0.005}, a, 7800, {-0.15, 0, 0})}};
  for (std::size_t l = 0; l < layouts.size(); ++l) {
    int departedParallel = 0, departedSerial = 0, ownersParallel = 0, ownersSerial = 0;
    const std::vector<State> parallel = run(PETSC_COMM_WORLD, layouts[l], departedParallel, ownersParallel);
    const std::vector<State> serial = run(PETSC_COMM_SELF, layouts[l], departedSerial, ownersSerial);
    REQUIRE(parallel.size() == 2);
    const double gap = norm(parallel[1].x - parallel[0].x) - 2 * a;
    INFO("layout " << l << ": gap " << gap / a << " a, separating at " << parallel[1].v.x - parallel[0].v.x
                   << ", sphere 2 in its window on " << ownersParallel << " ranks, at x " << parallel[1].x.x - xc << " from the boundary");
    CHECK(departedSerial);
    CHECK(departedParallel);
    CHECK(bitwiseEqual(parallel, serial));
    CHECK(gap > 0.25e-3);  // left the departure gap
    if (l == 1 && size > 1) CHECK(ownersParallel == 2);  // changed owner inside its window
  }
}
