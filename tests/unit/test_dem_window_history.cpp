// -contact_hydro_history: while the resolved force is excluded, the Basset history force of the
// velocity changes since the exclusion began acts instead, but not in contact: the contact's change
// enters the history as one change when it ends (docs/collisions.md). An elastic impact
// (restitution 1, no lubrication, -contact_hydro limit with the departure to a cell): the contact
// runs as without the force; after it, the velocity the sphere lacks against the run without the
// force is the force's impulse, which the test computes independently from the sphere's recorded
// velocity with the product integration of the whole record (BassetHistory).
#include "../support/DemFixtures.hpp"
#include "vp/interactions/BassetHistory.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

constexpr double kA = 1.5e-3, kSteel = 7800, kRho = 935, kMu = 0.05, kG = 9.81;
// The steel sphere's mass and the Basset force's factor: F = -kBassetK (the history integral).
const double kMass = kSteel * 4.0 / 3.0 * M_PI * kA * kA * kA, kBassetK = 6 * kA * kA * std::sqrt(M_PI * kRho * kMu);

struct Impact {
  std::vector<double> vz;           // after each fluid step
  std::vector<std::uint8_t> flags;  // after each fluid step
  bool modesCleared = true;         // no modes whenever the resolved force acts
};

Impact impact(bool history, double dt, int steps)
{
  Config c = boxConfig({0, 0, 0}, {0.018, 0.018, 0.018}, {36, 36, 36});  // a cell is a / 3
  c.fluid.off = false;
  c.fluid.rho = kRho;
  c.fluid.mu = kMu;
  c.gravity = {0, 0, -kG};
  ParticleConfig pc = contactConfig(1e-4, 1.0, 0.25);
  pc.contact.hydro = ContactHydro::Limit;
  pc.contact.departureCells = 1;
  pc.contact.hydroHistory = history;
  pc.substeps = 50;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.009, 0.009, kA + 2e-6}, kA, kSteel, {0, 0, -0.2})});
  ParticleStore& s = dem.particles();
  Impact out;
  out.vz.push_back(s.v[0].z);
  out.flags.push_back(0);
  for (int k = 0; k < steps; ++k) {
    s.fhyd[0] = (kRho / kSteel * s.mass[0] * kG) * Vec3{0, 0, 1};  // a still liquid's buoyancy
    dem.advance(k * dt, dt);
    out.vz.push_back(s.v[0].z);
    out.flags.push_back(s.flags[0]);
    if (!(s.flags[0] & (kResolvedForceOff | kDeparting))) out.modesCleared = out.modesCleared && s.windowHistory[0].empty();
  }
  REQUIRE(s.wallTouch[0] == 0);  // released, in free flight
  return out;
}

} // namespace

TEST_CASE("Window history: none in contact, then the contact's change acts as one at its end", "[dem][basset]")
{
  const double dt = 1e-6;  // a hundred samples over the 1e-4 s contact
  const int steps = 6000;
  const Impact with = impact(true, dt, steps), without = impact(false, dt, steps);
  // The window opens in the contact (first), the sphere leaves the wall (release) and departs to a
  // cell (last: the window's last step).
  int first = -1, release = -1, last = -1;
  for (int k = 0; k <= steps; ++k) {
    const bool window = with.flags[k] & (kResolvedForceOff | kDeparting);
    if (window && first < 0) first = k;
    if (window && release < 0 && first >= 0 && !(with.flags[k] & kTouching) && k > first) release = k;
    if (window) last = k;
  }
  REQUIRE(first > 0);
  REQUIRE(release > first);
  REQUIRE(last > release + 100);
  REQUIRE(last < steps);
  // In contact the sphere moves as without the force: the contact's impulse is the dry one.
  bool sameContact = true;
  for (int k = 0; k < release; ++k) sameContact = sameContact && with.vz[k] == without.vz[k] && with.flags[k] == without.flags[k];
  CHECK(sameContact);
  // The force's impulse over the window: no change recorded in the contact (its velocity held at the
  // window's start), the contact's change at the release, then the recorded velocity.
  BassetHistory record(dt, with.vz[first - 1]);
  for (int k = first; k < release; ++k) record.push(with.vz[first - 1]);
  double impulse = 0;
  for (int k = release; k <= last + 1; ++k) {
    record.push(with.vz[k]);
    impulse += -kBassetK * record.integral() * dt;
  }
  // After the window both fly under the same forces, so the difference stays.
  const double lacks = with.vz.back() - without.vz.back();
  INFO("rebound without " << without.vz.back() << ", with " << with.vz.back() << " m/s; difference " << lacks
                          << " m/s, the force's impulse / m " << impulse / kMass << " m/s; window steps " << first << "-" << last
                          << ", release " << release);
  CHECK(impulse < 0);
  CHECK(-lacks > 0.02 * -without.vz[0]);  // a real effect: a few per cent of the impact speed
  CHECK(std::fabs(lacks / (impulse / kMass) - 1) < 0.05);
  CHECK(with.modesCleared);
}

TEST_CASE("Window history: a small, light sphere in a viscous liquid stays stable (the kick's own change implicit)", "[dem][basset]")
{
  // a = 0.1 mm, rho_p 1100 in a liquid of rho 1000, mu 0.5, half kicks of 5e-5 s: 2 K sqrt(dt/2) / m
  // is about 7, where an explicit history force would grow without bound. After the contact
  // (elastic, 0.01 s) its change, about twice the impact speed, enters the history at once; the
  // departure (to 2 cells) is a window out of contact, where the force acts through the implicit kick.
  Config c = boxConfig({0, 0, 0}, {0.002, 0.002, 0.002}, {40, 40, 40});
  c.fluid.off = false;
  c.fluid.rho = 1000;
  c.fluid.mu = 0.5;
  c.gravity = {0, 0, -9.81};
  ParticleConfig pc = contactConfig(1e-2, 1.0, 0.25);  // no lubrication: its sub-step bound would rule
  pc.contact.hydro = ContactHydro::Limit;
  pc.contact.departureCells = 2;
  pc.contact.hydroHistory = true;
  pc.substeps = 1;
  const double a = 1e-4, dt = 1e-4, v0 = 0.01;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.001, 0.001, a + 1e-9}, a, 1100, {0, 0, -v0})});
  ParticleStore& s = dem.particles();
  // Without the force the elastic contact under the buoyant weight m g' peaks at sqrt(v0^2 + (g'/w)^2).
  const double gb = 9.81 * (1 - 1000.0 / 1100.0), w = M_PI / 1e-2, bound = std::sqrt(v0 * v0 + gb * gb / (w * w));
  double fastest = 0;
  int implicitKicks = 0;
  for (int k = 0; k < 400; ++k) {
    s.fhyd[0] = (1000.0 / 1100.0 * s.mass[0] * 9.81) * Vec3{0, 0, 1};
    dem.advance(k * dt, dt);
    fastest = std::max(fastest, norm(s.v[0]));
    implicitKicks += (s.flags[0] & kDeparting) && !(s.flags[0] & kTouching) && !s.windowHistory[0].empty();
  }
  INFO("fastest " << fastest << " m/s (impact " << v0 << ", bound " << bound << "), final vz " << s.v[0].z << ", steps departing "
                  << implicitKicks);
  CHECK(implicitKicks >= 3);
  CHECK(std::isfinite(fastest));
  CHECK(fastest <= 1.001 * bound);  // the history force takes energy, it never gives it
}

TEST_CASE("Window history: a re-contact inside a window fades the modes and adds its change at its end", "[dem][basset]")
{
  // A sphere between floor and ceiling with a cell of play: it leaves the floor after its impact, still
  // departing when it meets the ceiling, so one window holds two contacts, the second one with
  // modes already filled. No gravity and no lubrication: out of contact the history force alone
  // changes the velocity, which the test compares flight by flight with the force of an
  // independent record (BassetHistory) that holds the velocity through each contact and takes
  // its change at its end.
  const double gap = 5e-4, tc = 1e-3, dt = 4e-6, v0 = 0.2;
  Config c = boxConfig({0, 0, 0}, {0.018, 0.018, 2 * kA + gap}, {36, 36, 7});  // a cell is gap
  c.fluid.off = false;
  c.fluid.rho = kRho;
  c.fluid.mu = kMu;
  ParticleConfig pc = contactConfig(tc, 1.0, 0.25);
  pc.contact.hydro = ContactHydro::Limit;
  pc.contact.departureCells = 2;  // beyond the ceiling: departing from the floor until it touches
  pc.contact.hydroHistory = true;
  pc.substeps = 50;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.009, 0.009, kA + gap / 2}, kA, kSteel, {0, 0, -v0})});
  ParticleStore& s = dem.particles();
  const int steps = 3300;
  std::vector<double> vz{s.v[0].z};
  std::vector<std::uint8_t> flags{0};
  for (int k = 0; k < steps; ++k) {
    s.fhyd[0] = Vec3{};
    dem.advance(k * dt, dt);
    vz.push_back(s.v[0].z);
    flags.push_back(s.flags[0]);
  }
  const auto window = [&](int k) { return (flags[k] & (kResolvedForceOff | kDeparting)) != 0; };
  const auto touching = [&](int k) { return (flags[k] & kTouching) != 0; };
  int first = 1;
  while (first <= steps && !window(first)) ++first;
  REQUIRE(first < steps);
  REQUIRE(touching(first));
  // The contacts' start and end samples, and the window unbroken from the first on.
  std::vector<std::pair<int, int>> contacts;
  bool unbroken = true;
  for (int k = first; k <= steps; ++k) {
    unbroken = unbroken && window(k);
    if (touching(k) && !touching(k - 1)) contacts.push_back({k, steps + 1});
    if (!touching(k) && touching(k - 1)) contacts.back().second = k;
  }
  INFO(contacts.size() << " contacts, the first at sample " << contacts[0].first << "; vz at the end " << vz.back());
  REQUIRE(contacts.size() >= 3);  // floor, ceiling, floor
  REQUIRE(contacts[1].second <= steps);
  CHECK(unbroken);
  CHECK(vz[contacts[1].first - 1] > 0.5 * v0);  // the ceiling is met while still departing
  BassetHistory record(dt, vz[first - 1]);
  double held = vz[first - 1];
  std::vector<double> measured(2, 0.0), predicted(2, 0.0);
  for (int k = first; k < contacts[2].first; ++k) {
    if (!touching(k)) held = vz[k];
    record.push(held);
    // The flights between the contacts, their steps wholly out of contact.
    const int flight = k > contacts[0].second && k < contacts[1].first ? 0 : k > contacts[1].second ? 1 : -1;
    if (flight < 0) continue;
    measured[flight] += vz[k] - vz[k - 1];
    predicted[flight] += -kBassetK * record.integral() * dt / kMass;
  }
  for (int f = 0; f < 2; ++f) {
    INFO("flight " << f << ": velocity change " << measured[f] << " m/s, the force's impulse / m " << predicted[f]);
    CHECK(std::fabs(measured[f]) > 0.02 * v0);  // a real effect
    CHECK(std::fabs(measured[f] / predicted[f] - 1) < 0.03);
  }
}
