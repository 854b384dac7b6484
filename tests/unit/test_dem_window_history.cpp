// -contact_hydro_history: while the resolved force is excluded, the Basset history force of the
// velocity changes since the exclusion began acts instead (docs/collisions.md). An elastic
// impact (restitution 1, no lubrication, -contact_hydro exclude): gravity, buoyancy and the
// spring are conservative from touch-down to release, so the kinetic energy the sphere loses is
// the work of the history force alone, which the test computes independently from the sphere's
// recorded velocity with the product integration of the whole record (BassetHistory).
#include "../support/DemFixtures.hpp"
#include "vp/interactions/BassetHistory.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

constexpr double kA = 1.5e-3, kSteel = 7800, kRho = 935, kMu = 0.05, kG = 9.81;

struct Impact {
  std::vector<double> vz;     // after each fluid step
  double energy = 0;          // 0.5 m v^2 + m g' z at the end (g' the buoyant gravity)
  std::vector<bool> excluded; // the resolved force excluded during that step's last sub-step
  bool modesCleared = true;   // the modes are zero whenever the resolved force acts
};

Impact impact(bool history, double dt, int steps)
{
  Config c = boxConfig({0, 0, 0}, {0.018, 0.018, 0.018}, {36, 36, 36});
  c.fluid.off = false;
  c.fluid.rho = kRho;
  c.fluid.mu = kMu;
  c.gravity = {0, 0, -kG};
  ParticleConfig pc = contactConfig(1e-4, 1.0, 0.25);
  pc.contact.hydro = ContactHydro::Exclude;
  pc.contact.hydroHistory = history;
  pc.substeps = 50;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, pc, {sphere(1, {0.009, 0.009, kA + 2e-6}, kA, kSteel, {0, 0, -0.2})});
  ParticleStore& s = dem.particles();
  Impact out;
  out.vz.push_back(s.v[0].z);
  out.excluded.push_back(false);
  for (int k = 0; k < steps; ++k) {
    s.fhyd[0] = (kRho / kSteel * s.mass[0] * kG) * Vec3{0, 0, 1};  // a still liquid's buoyancy
    dem.advance(k * dt, dt);
    out.vz.push_back(s.v[0].z);
    const bool off = s.flags[0] & kResolvedForceOff;
    out.excluded.push_back(off);
    if (!off) out.modesCleared = out.modesCleared && s.windowHistory[0].empty();
  }
  REQUIRE(s.wallTouch[0] == 0);  // released, in free flight
  out.energy = s.mass[0] * (0.5 * dot(s.v[0], s.v[0]) + (1 - kRho / kSteel) * kG * s.x[0].z);
  return out;
}

} // namespace

TEST_CASE("Window history: an elastic impact loses the history force's work, and only while the resolved force is off", "[dem][basset]")
{
  const double dt = 1e-6;  // a hundred samples over the 1e-4 s contact
  const int steps = 400;
  const Impact with = impact(true, dt, steps), without = impact(false, dt, steps);
  const double m = kSteel * 4.0 / 3.0 * M_PI * kA * kA * kA, K = 6 * kA * kA * std::sqrt(M_PI * kRho * kMu);
  // The exclusion window: from the first step that ends in it to the last.
  int first = -1, last = -1;
  for (int k = 0; k <= steps; ++k)
    if (with.excluded[k]) last = k, first = first < 0 ? k : first;
  REQUIRE(first > 0);
  REQUIRE(last < steps);
  // The history force's work over the window, from the recorded velocity (samples at the steps;
  // the window opens between steps first - 1 and first).
  BassetHistory record(dt, with.vz[first - 1]);
  double work = 0;
  for (int k = first; k <= last + 1; ++k) {
    record.push(with.vz[k]);
    const double force = -K * record.integral();
    work += force * 0.5 * (with.vz[k] + with.vz[k - 1]) * dt;
  }
  // Gravity, buoyancy and the elastic spring conserve 0.5 m v^2 + m g' z from the start to the end
  // (in free flight after the release): what one run lacks of the other's is the history's work.
  const double lost = without.energy - with.energy, ke = 0.5 * m * without.vz[0] * without.vz[0];
  INFO("rebound without " << without.vz.back() << ", with " << with.vz.back() << " m/s; energy lost " << lost
                          << " J, the history force's work " << work << " J; window steps " << first << "-" << last);
  CHECK(work < 0);
  CHECK(-work > 0.02 * ke);  // a real effect: a few per cent of the impact's energy
  CHECK(std::fabs(lost / -work - 1) < 0.05);
  CHECK(with.modesCleared);
}

TEST_CASE("Window history: a small, light sphere in a viscous liquid stays stable (the kick's own change implicit)", "[dem][basset]")
{
  // a = 0.1 mm, rho_p 1100 in a liquid of rho 1000, mu 0.5, half kicks of 5e-5 s: 2 K sqrt(dt/2) / m
  // is about 7, where an explicit history force would grow without bound.
  Config c = boxConfig({0, 0, 0}, {0.002, 0.002, 0.002}, {8, 8, 8});
  c.fluid.off = false;
  c.fluid.rho = 1000;
  c.fluid.mu = 0.5;
  c.gravity = {0, 0, -9.81};
  ParticleConfig pc = contactConfig(1e-2, 1.0, 0.25);
  pc.contact.hydro = ContactHydro::Exclude;
  pc.contact.hydroHistory = true;
  pc.substeps = 1;
  const double a = 1e-4, dt = 1e-4;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, pc, {sphere(1, {0.001, 0.001, a + 1e-9}, a, 1100, {0, 0, -0.01})});
  ParticleStore& s = dem.particles();
  double fastest = 0;
  bool excluded = false;
  for (int k = 0; k < 400; ++k) {
    s.fhyd[0] = (1000.0 / 1100.0 * s.mass[0] * 9.81) * Vec3{0, 0, 1};
    dem.advance(k * dt, dt);
    fastest = std::max(fastest, norm(s.v[0]));
    excluded = excluded || (s.flags[0] & kResolvedForceOff);
  }
  INFO("fastest " << fastest << " m/s (impact 0.01 m/s), final vz " << s.v[0].z);
  CHECK(excluded);
  CHECK(std::isfinite(fastest));
  CHECK(fastest <= 0.0101);  // the history force takes energy, it never gives it
}
