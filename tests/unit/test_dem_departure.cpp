// -contact_hydro_departure (docs/collisions.md, "The departure after an impact"): which wall contacts
// start a departure, where it ends, and the correction it applies on the way out. The DEM of a
// coupled run without its fluid: the resolved force is held at the buoyancy of a still liquid.
#include "../support/DemFixtures.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

constexpr double kA = 1.5e-3, kSteel = 7800, kRho = 935, kMu = 0.05, kG = 9.81;
constexpr double kRough = 2e-4;  // of the diameter: contact from the gap 2 kRough a
constexpr int kCells = 72;       // d/dx 12: a cell is 0.25 mm

Config liquidBox()
{
  Config c = boxConfig({0, 0, 0}, {0.018, 0.018, 0.018}, {kCells, kCells, kCells});
  c.fluid.off = false;  // a coupled run: -contact_hydro applies
  c.fluid.rho = kRho;
  c.fluid.mu = kMu;
  c.gravity = {0, 0, -kG};
  return c;
}

ParticleConfig departureConfig(double cells)
{
  ParticleConfig pc = lubricatedConfig(1e-4, 0.97, kRough, LubModel::Llcm, 0);  // activation: 0.18 cells
  pc.contact.departureCells = cells;
  pc.substeps = 200;
  return pc;
}

struct Sample {
  double gap, vz;
  std::uint8_t flags;
};

// The sphere on the floor's axis from gap0 at speed vz0; the samples after each fluid step of dt.
std::vector<Sample> fall(double cells, double gap0, double vz0, int steps, double dt = 1e-5)
{
  const Config c = liquidBox();
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, departureConfig(cells)), {sphere(1, {0.009, 0.009, kA + gap0}, kA, kSteel, {0, 0, vz0})});
  ParticleStore& s = dem.particles();
  std::vector<Sample> out;
  for (int k = 0; k < steps; ++k) {
    s.fhyd[0] = (kRho / kSteel * s.mass[0] * kG) * Vec3{0, 0, 1};
    dem.advance(k * dt, dt);
    out.push_back({s.x[0].z - kA, s.v[0].z, s.flags[0]});
  }
  return out;
}

// The speed at which the gap opens (member `speed` of the samples) as it first passes `level`.
template <class S>
double openingSpeedAt(const std::vector<S>& run, double level, double S::*speed)
{
  for (size_t k = 1; k < run.size(); ++k)
    if (run[k].*speed > 0 && run[k - 1].gap < level && run[k].gap >= level) {
      const double w = (level - run[k - 1].gap) / (run[k].gap - run[k - 1].gap);
      return run[k - 1].*speed + w * (run[k].*speed - run[k - 1].*speed);
    }
  return NAN;
}

// The run with the departure opens its gap slower at `level` than the run without, by `expected`
// (within 2 %).
template <class S>
void checkSlowerBy(const std::vector<S>& with, const std::vector<S>& without, double S::*speed, double level, double expected)
{
  const double slow = openingSpeedAt(with, level, speed), fast = openingSpeedAt(without, level, speed);
  INFO("opening speed at a gap of " << level << " m: without " << fast << ", with " << slow << " m/s; difference "
                                    << fast - slow << " against " << expected);
  REQUIRE(expected > 0.01);
  CHECK(std::fabs((fast - slow) / expected - 1) < 0.02);
}

// The LLCM squeeze resistance (force per approach speed) of the sphere at wall gap h.
double resistance(double h)
{
  PairState st;
  st.normal = {0, 0, -1};
  st.gap = h;
  st.radiusI = kA;
  st.radiusJ = kWallRadius;
  st.velocityI = {0, 0, -1};
  st.viscosity = kMu;
  return std::fabs(lubricationModelForce(LubModel::Llcm, 1.0, st).forceI.z);
}

// The integral of R(h) - R(hAct) of a resistance R from the contact gap to hAct (midpoint rule in ln h).
double correctionIntegral(double (*R)(double), double hContact, double hAct)
{
  const int n = 4000;
  const double ratio = std::log(hAct / hContact), rAct = R(hAct);
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double h = hContact * std::exp((k + 0.5) / n * ratio);
    sum += (R(h) - rAct) * h;
  }
  return sum * ratio / n;
}

} // namespace

TEST_CASE("Departure: a wall impact starts it, it ends at the departure gap, the whole correction acts below it", "[dem][lub]")
{
  const double cell = 0.018 / kCells, C = 1.0;
  const std::vector<Sample> with = fall(C, 0.3e-3, -1.0, 150), without = fall(0, 0.3e-3, -1.0, 150);

  bool impact = false, inDeparture = false;
  for (const Sample& x : with) {
    impact = impact || (x.flags & kWallImpact);
    const bool departing = x.flags & kDeparting;
    INFO("gap " << x.gap / cell << " cells, vz " << x.vz << " m/s, flags " << int(x.flags));
    if (x.gap > 1.05 * C * cell) CHECK_FALSE(departing);  // ends at C cells
    if (x.vz < 0) CHECK_FALSE(departing);                 // only on the way out
    if (impact && x.vz > 0 && x.gap > 0 && x.gap < 0.95 * C * cell) CHECK(departing);
    inDeparture = inDeparture || departing;
  }
  CHECK(impact);
  CHECK(inDeparture);
  for (const Sample& x : without) CHECK_FALSE(x.flags & (kDeparting | kWallImpact));

  // Both runs are the same up to the end of the contact; on the way out the departure applies the
  // correction from C cells instead of the activation gap, so above C cells the sphere is slower
  // by (1/m) [int_hc^C (R - R(C)) dh - int_hc^act (R - R(act)) dh] (dv = -(R/m) dh at any speed).
  const double m = kSteel * 4.0 / 3.0 * M_PI * kA * kA * kA, hc = 2 * kRough * kA;
  const double expected = (correctionIntegral(resistance, hc, C * cell) - correctionIntegral(resistance, hc, 0.18 * cell)) / m;
  checkSlowerBy(with, without, &Sample::vz, 1.2 * C * cell, expected);
}

TEST_CASE("Departure: a sphere settling onto the wall and lifted from it never starts one", "[dem][lub]")
{
  // Released touching the wall at rest: the undamped spring would reach twice the buoyant-weight
  // overlap, the damped one (restitution 0.97) stays below it, so the contact is no impact.
  const double hc = 2 * kRough * kA;
  const Config c = liquidBox();
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, departureConfig(1.0)), {sphere(1, {0.009, 0.009, kA + 0.999 * hc}, kA, kSteel)});
  ParticleStore& s = dem.particles();
  const double dt = 1e-5;
  bool touched = false;
  for (int k = 0; k < 500; ++k) {
    if (k == 400) s.v[0].z = 0.05;  // lifted off at rest
    s.fhyd[0] = (kRho / kSteel * s.mass[0] * kG) * Vec3{0, 0, 1};
    dem.advance(k * dt, dt);
    touched = touched || s.x[0].z - kA < hc;
    INFO("step " << k << ": gap " << s.x[0].z - kA << " m, vz " << s.v[0].z);
    CHECK_FALSE(s.flags[0] & (kWallImpact | kDeparting));
  }
  CHECK(touched);
  CHECK(s.x[0].z - kA > hc);  // lifted off
}

namespace {

// The squeeze resistance of two equal spheres (force per approach speed) at gap h.
double pairResistance(double h)
{
  PairState st;
  st.normal = {1, 0, 0};
  st.gap = h;
  st.radiusI = st.radiusJ = kA;
  st.velocityI = {1, 0, 0};
  st.viscosity = kMu;
  return std::fabs(lubricationModelForce(LubModel::Llcm, 1.0, st).forceI.x);
}

struct PairSample {
  double gap, separation;  // surface gap and the speed at which it opens
  bool departing;          // both spheres flagged
  std::size_t rebuilds;
};

// Sphere 1 at 1 m/s onto sphere 2 at rest along x, no gravity (every contact is then an impact).
std::vector<PairSample> pairImpact(double cells)
{
  Config c = liquidBox();
  c.gravity = {0, 0, 0};
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  ParticleConfig pc = departureConfig(cells);
  pc.skin = 0.02;  // rebuilds the pair list during the departure: its state must survive them
  const double x0 = 0.009, half = kA + 0.15e-3;
  DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {x0 - half, 0.009, 0.009}, kA, kSteel, {1, 0, 0}), sphere(2, {x0 + half, 0.009, 0.009}, kA, kSteel)});
  ParticleStore& s = dem.particles();
  std::vector<PairSample> out;
  const double dt = 1e-5;
  for (int k = 0; k < 80; ++k) {
    dem.advance(k * dt, dt);
    const std::size_t a = s.id[0] == 1 ? 0 : 1, b = 1 - a;
    out.push_back({s.x[b].x - s.x[a].x - 2 * kA, s.v[b].x - s.v[a].x,
                   (s.flags[a] & kPairDeparting) && (s.flags[b] & kPairDeparting), dem.rebuilds()});
  }
  return out;
}

} // namespace

TEST_CASE("Departure of a pair: both spheres leave with the correction from C cells, across list rebuilds", "[dem][lub]")
{
  const double cell = 0.018 / kCells, C = 1.0;
  const std::vector<PairSample> with = pairImpact(C), without = pairImpact(0);
  bool departed = false, rebuiltWhileDeparting = false;
  for (size_t k = 1; k < with.size(); ++k) {
    const PairSample& x = with[k];
    INFO("gap " << x.gap / cell << " cells, separating at " << x.separation << " m/s");
    if (x.gap > 1.05 * C * cell || x.separation < 0) CHECK_FALSE(x.departing);
    if (x.separation > 0 && x.gap > 0 && x.gap < 0.95 * C * cell) CHECK(x.departing);
    departed = departed || x.departing;
    rebuiltWhileDeparting = rebuiltWhileDeparting || (x.departing && with[k - 1].departing && x.rebuilds > with[k - 1].rebuilds);
  }
  CHECK(departed);
  CHECK(rebuiltWhileDeparting);
  for (const PairSample& x : without) CHECK_FALSE(x.departing);

  // The relative motion has the reduced mass m/2: above C cells the pair separates slower than
  // without the option by (2/m) [int_hc^C (R - R(C)) dh - int_hc^act (R - R(act)) dh].
  const double m = kSteel * 4.0 / 3.0 * M_PI * kA * kA * kA, hc = kRough * 2 * kA;  // roughness of the mean diameter
  const double expected = 2 / m * (correctionIntegral(pairResistance, hc, C * cell) - correctionIntegral(pairResistance, hc, 0.18 * cell));
  checkSlowerBy(with, without, &PairSample::separation, 1.2 * C * cell, expected);
}

TEST_CASE("Departure of a pair: a sphere settling onto a fixed sphere and lifted from it never starts one", "[dem][lub]")
{
  // As at a wall: released touching at rest, the damped spring stays below twice the buoyant-weight
  // overlap, so the contact is no impact (the pair's threshold, with gravity).
  const Config c = liquidBox();
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  ParticleRecord anchor = sphere(1, {0.009, 0.009, 0.006}, kA, kSteel);
  anchor.flags = kFixed;
  const double hc = kRough * 2 * kA;  // the pair's contact gap: roughness of the mean diameter
  DemSolver dem(grid, c, resolved(c, departureConfig(1.0)), {anchor, sphere(2, {0.009, 0.009, 0.006 + 2 * kA + 0.999 * hc}, kA, kSteel)});
  ParticleStore& s = dem.particles();
  const std::size_t top = s.id[0] == 2 ? 0 : 1, bottom = 1 - top;
  const double dt = 1e-5;
  bool touched = false;
  for (int k = 0; k < 500; ++k) {
    if (k == 400) s.v[top].z = 0.05;  // lifted off at rest
    s.fhyd[top] = (kRho / kSteel * s.mass[top] * kG) * Vec3{0, 0, 1};
    dem.advance(k * dt, dt);
    const double gap = s.x[top].z - s.x[bottom].z - 2 * kA;
    touched = touched || gap < hc;
    INFO("step " << k << ": gap " << gap << " m, vz " << s.v[top].z);
    CHECK_FALSE(s.flags[top] & kPairDeparting);
  }
  CHECK(touched);
  CHECK(s.x[top].z - s.x[bottom].z - 2 * kA > hc);  // lifted off
}

TEST_CASE("Departure: a sphere that turns back within the departure gap ends it", "[dem][lub]")
{
  // A slow impact (St about 5): the sphere leaves the wall but the film and its weight turn it back
  // within C = 1 cell; from then on it is no longer leaving, down to the next contact.
  const double cell = 0.018 / kCells;
  const std::vector<Sample> run = fall(1.0, 0.3e-3, -0.1, 1500);
  bool departed = false, turnedBack = false;
  for (size_t k = 1; k < run.size(); ++k) {
    const Sample& x = run[k];
    INFO("step " << k << ": gap " << x.gap / cell << " cells, vz " << x.vz << " m/s, flags " << int(x.flags));
    departed = departed || (x.flags & kDeparting);
    if (departed && x.vz < 0 && x.gap > 0) {
      turnedBack = true;
      CHECK_FALSE(x.flags & kDeparting);
    }
    if (departed) CHECK(x.gap < cell);  // it never gets beyond the departure gap
  }
  CHECK(departed);
  CHECK(turnedBack);
}
