// Rank-count invariance: contacts split across rank boundaries (sliding, sticking, a sphere sliding
// along a wall from rank to rank) and the dry granular collapse give bitwise the same particles on
// any number of ranks as on one.
#include "../support/DemFixtures.hpp"
#include "vp/particles/Generators.hpp"
#include <catch2/catch.hpp>
#include <random>

using namespace vp;
using namespace vp::test;

namespace {

// Runs the steps; `shared` tells whether every rank owned particles at the start.
std::vector<State> run(MPI_Comm comm, const Config& c, const ParticleConfig& pc, const std::vector<ParticleRecord>& p,
                       double dt, int steps, bool* shared = nullptr)
{
  Grid grid(comm, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), p);
  if (shared) *shared = allRanks(comm, dem.particles().nOwned > 0);
  for (int k = 0; k < steps; ++k) dem.advance(k * dt, dt);
  return gatherState(comm, dem.particles());
}

} // namespace

TEST_CASE("Sliding and sticking contacts across rank boundaries equal the one-rank result", "[mpi][particles]")
{
  Config c = boxConfig({0, 0, 0}, {1, 0.4, 0.4}, {12, 2, 2});
  c.gravity = {0, 0, -9.81};
  ParticleConfig pc = contactConfig(0.01, 0.8, 0.3);
  pc.contact.rollingFriction = 0.02;  // its torque across rank boundaries too
  const double a = 0.05;
  std::vector<ParticleRecord> p = {
    // Sliding pair around x = 1/3: tangential speed well above the critical incidence.
    sphere(1, {1.0 / 3 - 0.06, 0.15, 0.25}, a, 2000, {0.2, 0.6, 0.1}),
    sphere(2, {1.0 / 3 + 0.06, 0.18, 0.25}, a, 2500, {-0.2, -0.5, 0}, {0, 3, 0}),
    // Sticking pair around x = 1/2: small tangential speed.
    sphere(3, {0.5 - 0.06, 0.20, 0.25}, a, 2000, {0.2, 0.01, 0}),
    sphere(4, {0.5 + 0.06, 0.20, 0.26}, a, 2000, {-0.2, 0, 0}, {0, 0, 0.5}),
    // Sliding pair around x = 2/3 with spin.
    sphere(5, {2.0 / 3 - 0.06, 0.18, 0.2}, a, 2000, {0.25, 0.3, 0}, {10, 0, -5}),
    sphere(6, {2.0 / 3 + 0.06, 0.20, 0.2}, a, 2000, {-0.1, 0, 0.3}),
    // Sliding then rolling along the floor across every rank boundary, carrying its wall spring.
    sphere(7, {0.1, 0.35 - 1e-3, a}, a, 2500, {2.5, 0, 0}),
  };
  const double dt = 0.01 / 50;
  const std::vector<State> parallel = run(PETSC_COMM_WORLD, c, pc, p, dt, 2000);
  const std::vector<State> serial = run(PETSC_COMM_SELF, c, pc, p, dt, 2000);
  REQUIRE(parallel.size() == p.size());
  // The rolling sphere really crossed the domain.
  INFO("rolling sphere at x = " << parallel[6].x.x);
  CHECK(parallel[6].x.x > 0.7);
  CHECK(bitwiseEqual(parallel, serial));
}

TEST_CASE("Dry granular collapse: 2000 steps bitwise identical to one rank", "[mpi][particles][collapse]")
{
  // The benchmark case (benchmarks/dem): 2000 settled spheres,
  // kn = 200 N/m, e = 0.9, mu = 0.25, dt = 3.6e-6 s, walls all round.
  Config c = boxConfig({0, 0, 0}, {0.15, 0.0105, 0.04}, {4, 32, 4});
  c.gravity = {0, 0, -9.81};
  ParticleConfig pc;
  pc.contact.kn = 200;
  pc.contact.restitution = 0.9;
  pc.contact.friction = 0.25;
  const std::vector<ParticleRecord> p = readParticleCsv(VP_SOURCE_DIR "/cases/data/column_2000.csv");
  REQUIRE(p.size() == 2000);
  bool shared = false;
  const std::vector<State> parallel = run(PETSC_COMM_WORLD, c, pc, p, 3.6e-6, 2000, &shared);
  CHECK(shared);  // the decomposition (split along y, like the LAMMPS runs) cuts the column
  const std::vector<State> serial = run(PETSC_COMM_SELF, c, pc, p, 3.6e-6, 2000);
  REQUIRE(parallel.size() == 2000);
  double maxSpeed = 0;
  for (const State& s : serial) maxSpeed = std::max(maxSpeed, norm(s.v));
  CHECK(maxSpeed > 0.01);  // the column is collapsing
  CHECK(bitwiseEqual(parallel, serial));
}

TEST_CASE("A periodic box two halos wide: colliding spheres bitwise identical to one rank", "[mpi][particles][ghosts]")
{
  // Twelve spheres of radius 0.06-0.08 in a fully periodic 0.4 m box: the halo (2 a_max + skin,
  // 0.176 m) is wider than a subdomain on 3 or 4 ranks and nearly half the box, so ghosts travel
  // over more than one subdomain and a rank holds images of its own spheres.
  Config c = boxConfig({0, 0, 0}, {0.4, 0.4, 0.4}, {8, 8, 8}, true);
  ParticleConfig pc = contactConfig(0.01, 0.8, 0.3);
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<ParticleRecord> p;
  while (p.size() < 12) {
    const Vec3 x{0.4 * u(), 0.4 * u(), 0.4 * u()};
    const double a = 0.06 + 0.02 * u();
    bool free = true;
    for (const ParticleRecord& q : p) {
      Vec3 d = x - q.x;
      for (int k = 0; k < 3; ++k) d[k] -= 0.4 * std::round(d[k] / 0.4);
      free = free && norm(d) > a + q.radius;
    }
    if (free)
      p.push_back(sphere(static_cast<std::int64_t>(p.size()), x, a, 2000, {4 * u() - 2, 4 * u() - 2, 4 * u() - 2}));
  }
  const double dt = 0.01 / 50;
  const std::vector<State> parallel = run(PETSC_COMM_WORLD, c, pc, p, dt, 1500);
  const std::vector<State> serial = run(PETSC_COMM_SELF, c, pc, p, dt, 1500);
  REQUIRE(parallel.size() == p.size());
  // Collisions happened: the speeds changed.
  double change = 0;
  for (std::size_t i = 0; i < p.size(); ++i) change = std::max(change, norm(serial[i].v - p[i].v));
  CHECK(change > 0.5);
  CHECK(bitwiseEqual(parallel, serial));
}

TEST_CASE("Spheroid contacts and squeeze films across rank boundaries equal the one-rank result", "[mpi][particles][shape]")
{
  Config c = boxConfig({0, 0, 0}, {1, 0.4, 0.4}, {12, 2, 2});
  c.gravity = {0, 0, -9.81};
  c.fluid.mu = 0.05;  // the squeeze acts from a gap of half a radius on
  ParticleConfig pc = lubricatedConfig(0.01, 0.8, 1e-3, LubModel::Llcm, 0.5);
  pc.contact.friction = 0.3;
  const double a = 0.04;
  auto body = [&](std::int64_t id, Vec3 x, double aspect, Vec3 axis, Vec3 v, Vec3 w = {}) {
    return spheroid(id, x, a, aspect, axis, 2000, v, w);
  };
  std::vector<ParticleRecord> p = {
    // Prolate against oblate around x = 1/3, off-centre and spinning; a prolate against a sphere
    // around x = 2/3; a tilted prolate falling onto the floor and sliding across the boundaries.
    body(1, {1.0 / 3 - 0.09, 0.15, 0.25}, 2, {1, 0.3, 0.2}, {0.3, 0, 0.05}, {0, 4, 0}),
    body(2, {1.0 / 3 + 0.07, 0.18, 0.27}, 0.5, {0.2, 0, 1}, {-0.2, 0, 0}),
    body(3, {2.0 / 3 - 0.1, 0.2, 0.2}, 2, {0.6, 0.6, 0.5}, {0.3, 0, 0.1}, {5, 0, -3}),
    sphere(4, {2.0 / 3 + 0.06, 0.21, 0.2}, a, 2000, {-0.1, 0, 0}),
    body(5, {0.1, 0.3, 0.12}, 2, {1, 0, 1}, {2.0, 0, 0}),
  };
  const double dt = 0.01 / 50;
  long contactSteps = 0;
  std::vector<State> parallel;
  {
    Grid grid(PETSC_COMM_WORLD, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc), p);
    for (int k = 0; k < 2000; ++k) {
      dem.advance(k * dt, dt);
      contactSteps += dem.diagnostics().contacts;
    }
    parallel = gatherState(PETSC_COMM_WORLD, dem.particles());
  }
  const std::vector<State> serial = run(PETSC_COMM_SELF, c, pc, p, dt, 2000);
  REQUIRE(parallel.size() == p.size());
  INFO("sliding spheroid at x = " << parallel[4].x.x << ", pair contact steps " << contactSteps);
  CHECK(parallel[4].x.x > 0.5);
  CHECK(contactSteps > 50);  // both pairs touch
  CHECK(bitwiseEqual(parallel, serial));
  // The films acted: without them (same contact law) the bodies leave otherwise.
  ParticleConfig dry = pc;
  dry.lubrication.model = LubModel::None;
  const std::vector<State> unlubricated = run(PETSC_COMM_SELF, c, dry, p, dt, 2000);
  double change = 0;
  for (std::size_t i = 0; i < p.size(); ++i) change = std::max(change, norm(unlubricated[i].v - serial[i].v));
  CHECK(change > 0.01);
}
