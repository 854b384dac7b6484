// Lubrication in the DEM pair loop (-lub_model): a sphere pushed towards a wall by a constant force
// approaches at the quasi-steady speed set by the lubrication drag.
#include "../support/DemFixtures.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

struct Crossing {
  double speed;  // approach speed when the gap crossed eps (m/s)
  bool reached;
};

// Drops a sphere from gap 0.09 a onto the floor under gravity (the constant force) with the model,
// and records the approach speed as the gap passes each of eps (fractions of the radius).
std::vector<Crossing> approach(LubModel model, const std::vector<double>& eps, double a, double mu, double g)
{
  Config c = boxConfig({0, 0, 0}, {0.01, 0.01, 0.01}, {2, 2, 2});
  c.gravity = {0, 0, -g};
  c.fluid.mu = mu;
  // Saturation 2 * 2.5e-3 = 5e-3 of the radius, below the gaps probed; the saturated dashpot then
  // allows sub-steps up to m / (2 c) = 1.9e-6 s.
  const ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 2.5e-3, model, 0.1);
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.005, 0.005, a * 1.09}, a, 1000)});
  const ParticleStore& s = dem.particles();
  std::vector<Crossing> out(eps.size(), Crossing{0, false});
  const double dt = 1e-6;
  double gapOld = s.x[0].z - a, speedOld = 0;
  for (int k = 0; k < 400000 && !out.back().reached; ++k) {
    dem.advance(k * dt, dt);
    const double gap = s.x[0].z - a, speed = -s.v[0].z;
    for (size_t e = 0; e < eps.size(); ++e) {
      const double h = eps[e] * a;
      if (!out[e].reached && gap <= h) {
        const double w = (gapOld - h) / (gapOld - gap);  // linear interpolation within the step
        out[e] = {speedOld + w * (speed - speedOld), true};
      }
    }
    gapOld = gap;
    speedOld = speed;
  }
  return out;
}

// Squeeze resistance F/U of a model at gap eps*a for a sphere approaching a wall.
double resistance(LubModel model, double eps, double a, double mu)
{
  PairState st;
  st.normal = {0, 0, -1};
  st.gap = eps * a;
  st.radiusI = a;
  st.radiusJ = kWallRadius;
  st.velocityI = {0, 0, -1};
  st.viscosity = mu;
  return lubricationModelForce(model, 1.0, st).forceI.z;
}

} // namespace

TEST_CASE("DEM with -lub_model blcm: constant-force approach at U = F / (6 pi mu a (1/eps - 1/eps_act))", "[dem][lub]")
{
  const double a = 1e-3, mu = 0.3, g = 9.81;
  const double F = 1000 * 4.0 / 3.0 * M_PI * a * a * a * g;
  const std::vector<double> eps = {0.03, 0.01};
  const std::vector<Crossing> got = approach(LubModel::Blcm, eps, a, mu, g);
  for (size_t e = 0; e < eps.size(); ++e) {
    const double expected = F / (6 * M_PI * mu * a * (1 / eps[e] - 1 / 0.1));
    INFO("eps " << eps[e] << ": approach speed " << got[e].speed << " vs quasi-steady " << expected);
    REQUIRE(got[e].reached);
    CHECK(std::fabs(got[e].speed / expected - 1) <= 0.01);
  }
}

TEST_CASE("DEM with -lub_model llcm: quasi-steady approach with the LLCM squeeze resistance", "[dem][lub]")
{
  const double a = 1e-3, mu = 0.3, g = 9.81;
  const double F = 1000 * 4.0 / 3.0 * M_PI * a * a * a * g;
  const std::vector<double> eps = {0.03, 0.01};
  const std::vector<Crossing> got = approach(LubModel::Llcm, eps, a, mu, g);
  for (size_t e = 0; e < eps.size(); ++e) {
    const double expected = F / (resistance(LubModel::Llcm, eps[e], a, mu) - resistance(LubModel::Llcm, 0.1, a, mu));
    INFO("eps " << eps[e] << ": approach speed " << got[e].speed << " vs quasi-steady " << expected);
    REQUIRE(got[e].reached);
    CHECK(std::fabs(got[e].speed / expected - 1) <= 0.01);
  }
}
