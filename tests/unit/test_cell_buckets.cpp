// Cell buckets over occupied space: every pair closer than the cell size is a candidate exactly
// once, in the dense layout (a packed cloud) and in the hashed one (spheres scattered in a large
// box), and the storage follows the particles, not the box.
#include "vp/particles/CellBuckets.hpp"
#include <catch2/catch.hpp>
#include <random>
#include <set>

using namespace vp;

namespace {

// Candidate pairs (i < j) and whether each close pair is among them, exactly once.
void checkComplete(const std::vector<Vec3>& x, std::size_t nOwned, const CellBuckets& b, double range)
{
  std::multiset<std::pair<std::size_t, std::size_t>> found;
  b.forEachCandidate(nOwned, [&](std::size_t i, std::size_t j) { found.insert({std::min(i, j), std::max(i, j)}); });
  for (const auto& p : found) CHECK(found.count(p) == 1);
  for (std::size_t i = 0; i < nOwned; ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const Vec3 d = x[i] - x[j];
      if (dot(d, d) < range * range) CHECK(found.count({i, j}) == 1);
    }
}

} // namespace

TEST_CASE("cell buckets find every close pair, dense and hashed", "[dem]")
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const double range = 0.05;
  SECTION("a packed cloud: dense")
  {
    std::vector<Vec3> x;
    for (int i = 0; i < 2000; ++i) x.push_back({0.2 + 0.3 * u(rng), 0.1 + 0.5 * u(rng), 0.3 * u(rng)});
    CellBuckets b;
    b.build(x, x.size(), {0, 0, 0}, {1, 1, 1}, range);
    CHECK_FALSE(b.hashed());
    checkComplete(x, 1500, b, range);  // the last 500 play ghosts
  }
  SECTION("a few spheres scattered in a large box: hashed")
  {
    std::vector<Vec3> x;
    for (int i = 0; i < 300; ++i) x.push_back({100 * u(rng), 100 * u(rng), 100 * u(rng)});
    for (int i = 0; i < 200; ++i) x.push_back({50 + 0.2 * u(rng), 50 + 0.2 * u(rng), 50 + 0.2 * u(rng)});  // a cluster
    CellBuckets b;
    b.build(x, x.size(), {0, 0, 0}, {100, 100, 100}, range);
    CHECK(b.hashed());
    CHECK(b.cellsStored() <= x.size());
    checkComplete(x, 400, b, range);
  }
  SECTION("one sphere in a box of 10^12 cells: one cell")
  {
    const std::vector<Vec3> x{{0.5, 0.5, 0.5}};
    CellBuckets b;
    b.build(x, 1, {0, 0, 0}, {1, 1, 1}, 1e-4);
    CHECK(b.cellsStored() == 1);
  }
}
