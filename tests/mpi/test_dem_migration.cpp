// No particle lost or duplicated: 10^4 particles random-walk through a fully periodic box and are
// handed between ranks (and wrapped) for at least 10^4 migrations; the global id set and every
// trajectory stay exactly what a serial replay of the same walk gives.
#include "../support/DemFixtures.hpp"
#include "vp/particles/Exchange.hpp"
#include <catch2/catch.hpp>
#include <random>

using namespace vp;
using namespace vp::test;

namespace {

// Step of particle `id` at walk step `step`: uniform in [-0.04, 0.04]^3, the same on any rank.
Vec3 walkStep(std::int64_t id, int step)
{
  std::mt19937_64 rng(static_cast<std::uint64_t>(id) * 1000003ULL + static_cast<std::uint64_t>(step));
  Vec3 d;
  for (int k = 0; k < 3; ++k) d[k] = 0.08 * (static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5);
  return d;
}

} // namespace

TEST_CASE("Random walk with periodic wrap: no particle lost or duplicated", "[mpi][particles][migration]")
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {12, 12, 12}, true);
  Grid grid(comm, c.grid, c.bc);
  ParticleExchange ex(grid, 0.05);
  const int n = 10000, steps = 40;
  std::mt19937_64 rng(7);
  std::vector<Vec3> expected(n);
  ParticleStore s;
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) expected[i][d] = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    if (ex.owns(expected[i])) s.append(sphere(i, expected[i], 0.01, 1000));
  }
  s.nOwned = s.size();
  long migrations = 0;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < s.nOwned; ++i) s.x[i] += walkStep(s.id[i], step);
    migrations += static_cast<long>(ex.migrate(s));
    if (step % 10 == 0) ex.createGhosts(s);  // ghosts in between must not disturb ownership
    for (int i = 0; i < n; ++i) expected[i] = ex.wrapped(expected[i] + walkStep(i, step));
  }
  s.dropGhosts();
  long total = 0;
  MPI_Allreduce(&migrations, &total, 1, MPI_LONG, MPI_SUM, comm);
  bool inBox = true;
  for (std::size_t i = 0; i < s.nOwned; ++i) inBox = inBox && ex.owns(s.x[i]);
  const std::vector<State> all = gatherState(comm, s);
  bool ids = all.size() == static_cast<std::size_t>(n), positions = ids;
  for (std::size_t i = 0; ids && i < all.size(); ++i) {
    ids = all[i].id == static_cast<std::int64_t>(i);
    positions = positions && ids && all[i].x.x == expected[i].x && all[i].x.y == expected[i].y && all[i].x.z == expected[i].z;
  }
  int size;
  MPI_Comm_size(comm, &size);
  INFO("migrations " << total << ", particles " << all.size());
  // One rank wraps its particles in place: nothing is sent.
  CHECK(total >= (size > 1 ? 10000 : 0));
  CHECK(allRanks(comm, inBox));
  CHECK(ids);
  CHECK(positions);
}
