// Ghosts complete: the partners each owned particle finds through ghosts and CellBuckets equal a
// brute-force search over all particles with periodic images; refreshed ghosts sit exactly at their
// owner's position (up to a periodic shift).
#include "../support/DemFixtures.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/Exchange.hpp"
#include <catch2/catch.hpp>
#include <map>
#include <random>
#include <set>

using namespace vp;
using namespace vp::test;

namespace {

// n spheres of radius [rmin, 2 rmin) at random in a box with periodic x and z and walls in y; pairs
// closer than a_i + a_j + extra; halo 4 rmin + extra.
void checkGhostPairs(const Vec3& L, std::array<int, 3> cells, int n, double rmin, double extra, long minPairs)
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Config c = boxConfig({0, 0, 0}, L, cells, true);
  c.bc.type[2] = c.bc.type[3] = BcType::Wall;
  Grid grid(comm, c.grid, c.bc);
  const double halo = 4 * rmin + extra;
  ParticleExchange ex(grid, halo);
  std::mt19937_64 rng(11);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<ParticleRecord> all(n);
  ParticleStore s;
  for (int i = 0; i < n; ++i) {
    all[i] = sphere(i, {L[0] * u(), L[1] * u(), L[2] * u()}, rmin + rmin * u(), 1000);
    if (ex.owns(all[i].x)) s.append(all[i]);
  }
  s.nOwned = s.size();
  ex.createGhosts(s);

  const bool periodic[3] = {true, false, true};
  auto near = [&](const ParticleRecord& a, const ParticleRecord& b) {
    Vec3 d = a.x - b.x;
    for (int k = 0; k < 3; ++k)
      if (periodic[k]) d[k] -= L[k] * std::round(d[k] / L[k]);
    const double range = a.radius + b.radius + extra;
    return dot(d, d) < range * range;
  };
  auto checkPairs = [&]() {
    CellBuckets buckets;
    Vec3 lo, hi;
    for (int d = 0; d < 3; ++d) {
      lo[d] = ex.boxLo(d) - halo;
      hi[d] = ex.boxHi(d) + halo;
    }
    buckets.build(s.x, s.size(), lo, hi, halo);
    std::map<std::int64_t, std::set<std::int64_t>> found;
    for (std::size_t i = 0; i < s.nOwned; ++i) found[s.id[i]];
    buckets.forEachCandidate(s.nOwned, [&](std::size_t i, std::size_t j) {
      const double range = s.radius[i] + s.radius[j] + extra;
      const Vec3 d = s.x[i] - s.x[j];
      if (dot(d, d) >= range * range) return;
      found[s.id[i]].insert(s.id[j]);
      if (j < s.nOwned) found[s.id[j]].insert(s.id[i]);
    });
    long mismatches = 0, pairs = 0;
    for (auto& [id, partners] : found) {
      std::set<std::int64_t> expected;
      for (int j = 0; j < n; ++j)
        if (j != id && near(all[id], all[j])) expected.insert(j);
      mismatches += partners != expected;
      pairs += static_cast<long>(expected.size());
    }
    long global[2], local[2] = {mismatches, pairs};
    MPI_Allreduce(local, global, 2, MPI_LONG, MPI_SUM, comm);
    return std::pair<long, long>{global[0], global[1]};
  };

  auto [mismatches, pairs] = checkPairs();
  INFO("partner entries " << pairs);
  REQUIRE(pairs > minPairs);
  CHECK(mismatches == 0);

  // Move every particle a little (less than the halo margin) and refresh the ghosts only.
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const Vec3 d{0.002 * std::sin(1.0 * s.id[i]), 0.002 * std::cos(2.0 * s.id[i]), 0.002 * std::sin(3.0 * s.id[i])};
    s.x[i] += d;
  }
  for (auto& r : all) r.x += Vec3{0.002 * std::sin(1.0 * r.id), 0.002 * std::cos(2.0 * r.id), 0.002 * std::sin(3.0 * r.id)};
  ex.updateGhosts(s);
  bool exact = true;
  for (std::size_t g = s.nOwned; g < s.size(); ++g)
    for (int k = 0; k < 3; ++k) {
      const double d = s.x[g][k] - all[s.id[g]].x[k];
      exact = exact && (periodic[k] ? std::fabs(d - L[k] * std::round(d / L[k])) < 1e-12 : d == 0);
    }
  CHECK(allRanks(comm, exact));
}

} // namespace

TEST_CASE("Bucket pairs through ghosts equal brute-force pairs", "[mpi][particles][ghosts]")
{
  checkGhostPairs({1, 0.8, 0.6}, {10, 8, 6}, 3000, 0.01, 0.01, 1000);
}

TEST_CASE("Ghosts across several subdomains: a periodic box two halos wide", "[mpi][particles][ghosts]")
{
  // Halo 0.4 in a 0.8 x 0.8 x 0.8 box of 8 cells a side: on 2-4 ranks a subdomain is 0.2-0.4 wide,
  // so ghosts cross more than one of them, and every rank holds images of its own spheres.
  checkGhostPairs({0.8, 0.8, 0.8}, {8, 8, 8}, 150, 0.09, 0.04, 200);
}
