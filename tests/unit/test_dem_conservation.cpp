// Conservation in the DEM: an isolated pair collision with friction and spin conserves linear and
// angular momentum to round-off; a damped system never gains kinetic energy.
#include "../support/DemFixtures.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace vp;
using namespace vp::test;

TEST_CASE("Isolated oblique pair collision conserves linear and angular momentum", "[dem]")
{
  Config c = boxConfig({0, 0, 0}, {0.1, 0.1, 0.1}, {4, 4, 4});
  ParticleConfig pc = contactConfig(1e-3, 0.8, 0.4);
  const double a1 = 0.005, a2 = 0.008;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  // Off-centre, spinning, unequal: the contact slides first, then sticks.
  DemSolver dem(grid, c, resolved(c, pc),
                {sphere(3, {0.040, 0.050, 0.050}, a1, 2500, {0.2, 0.01, -0.03}, {5, -20, 30}),
                 sphere(9, {0.0535, 0.056, 0.052}, a2, 1200, {-0.1, 0, 0.02}, {-10, 4, 0})});
  const ParticleStore& s = dem.particles();
  auto momenta = [&](Vec3& P, Vec3& L, double& Pscale, double& Lscale) {
    P = L = Vec3{};
    Pscale = Lscale = 0;
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      const double m = s.mass[i], I = 0.4 * m * s.radius[i] * s.radius[i];
      P += m * s.v[i];
      L += cross(s.x[i], m * s.v[i]) + I * s.w[i];
      Pscale += m * norm(s.v[i]);
      Lscale += norm(s.x[i]) * m * norm(s.v[i]) + I * norm(s.w[i]);
    }
  };
  Vec3 P0, L0, P, L;
  double ps, ls;
  momenta(P0, L0, ps, ls);
  double worstP = 0, worstL = 0;
  long contactSteps = 0;
  for (int step = 0; step < 400; ++step) {
    dem.advance(0, 1e-3 / 50);
    contactSteps += dem.diagnostics().contacts;
    momenta(P, L, ps, ls);
    worstP = std::max(worstP, norm(P - P0) / ps);
    worstL = std::max(worstL, norm(L - L0) / ls);
  }
  REQUIRE(contactSteps > 20);  // the spheres did collide
  CHECK(worstP < 1e-14);
  CHECK(worstL < 1e-14);
}

TEST_CASE("Kinetic energy of a damped granular gas never increases", "[dem]")
{
  Config c = boxConfig({0, 0, 0}, {0.06, 0.06, 0.06}, {4, 4, 4});
  ParticleConfig pc = contactConfig(1e-3, 0.8, 0.3);
  std::mt19937_64 rng(42);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5; };
  std::vector<ParticleRecord> p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        p.push_back(sphere(static_cast<std::int64_t>(p.size()), {0.01 + 0.02 * i, 0.01 + 0.02 * j, 0.01 + 0.02 * k}, 0.004,
                           2500, {0.4 * u(), 0.4 * u(), 0.4 * u()}, {100 * u(), 100 * u(), 100 * u()}));
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), p);
  // Springs store energy during a contact, so compare the kinetic energy at contact-free instants.
  double previous = dem.diagnostics().kineticEnergy;
  const double initial = previous;
  int freeInstants = 0, increases = 0;
  for (int step = 0; step < 20000; ++step) {
    dem.advance(0, 1e-3 / 50);
    const DemDiagnostics d = dem.diagnostics();
    if (d.contacts + d.wallContacts > 0) continue;
    ++freeInstants;
    increases += d.kineticEnergy > previous;
    previous = d.kineticEnergy;
  }
  INFO("contact-free instants " << freeInstants << ", final/initial energy " << previous / initial);
  REQUIRE(freeInstants > 100);
  CHECK(previous < 0.5 * initial);  // many collisions happened
  CHECK(increases == 0);
}

TEST_CASE("A free spinning sphere turns its orientation by omega t; -dem_orientation false keeps it", "[dem]")
{
  Config c = boxConfig({0, 0, 0}, {0.1, 0.1, 0.1}, {4, 4, 4});
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  const Vec3 w{3, -4, 12};  // |w| = 13 rad/s about a fixed axis (no torque)
  for (const bool integrate : {true, false}) {
    ParticleConfig pc = contactConfig(1e-3, 0.8, 0.4);
    pc.orientation = integrate;
    DemSolver dem(grid, c, resolved(c, pc), {sphere(0, {0.05, 0.05, 0.05}, 0.005, 2500, {}, w)});
    const int steps = 1000;
    const double dt = 1e-4;
    for (int k = 0; k < steps; ++k) dem.advance(k * dt, dt);
    const Quaternion q = dem.particles().q[0];
    // Exact: rotation by |w| t = 1.3 rad about w / |w|, from the identity.
    const double half = 0.5 * 13 * steps * dt, s = std::sin(half) / 13;
    const Quaternion expect = integrate ? Quaternion{std::cos(half), s * w.x, s * w.y, s * w.z} : Quaternion{};
    CHECK(std::fabs(q.w - expect.w) < 1e-12);
    CHECK(std::fabs(q.x - expect.x) < 1e-12);
    CHECK(std::fabs(q.y - expect.y) < 1e-12);
    CHECK(std::fabs(q.z - expect.z) < 1e-12);
  }
}
