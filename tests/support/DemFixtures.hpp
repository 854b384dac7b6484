#pragma once
// Small builders shared by the particle tests: a configuration in code, particles, a state gather.
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/particles/DemSolver.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include <algorithm>
#include <vector>

namespace vp::test {

inline Config boxConfig(Vec3 lo, Vec3 hi, std::array<int, 3> cells, bool periodic = false)
{
  Config c;
  c.fluid.off = true;
  c.grid.n = cells;
  for (int d = 0; d < 3; ++d) {
    c.grid.lo[d] = lo[d];
    c.grid.hi[d] = hi[d];
  }
  for (int f = 0; f < 6; ++f) c.bc.type[f] = periodic ? BcType::Periodic : BcType::Wall;
  return c;
}

inline ParticleConfig contactConfig(double tc, double restitution, double friction)
{
  ParticleConfig pc;
  pc.contact.tc = tc;
  pc.contact.restitution = restitution;
  pc.contact.friction = friction;
  return pc;
}

// A contact law with a roughness gap (fraction of the diameter) and a lubrication model acting from
// the gap eps_act = activation (fraction of the radius); the saturation is the roughness gap.
inline ParticleConfig lubricatedConfig(double tc, double restitution, double roughness, LubModel model,
                                       double activation)
{
  ParticleConfig pc = contactConfig(tc, restitution, 0.25);
  pc.contact.roughness = roughness;
  pc.lubrication.model = model;
  pc.lubrication.activation = activation;
  return pc;
}

// pc with the defaults the run's configuration resolves (a DemSolver requires them).
inline ParticleConfig resolved(const Config& c, ParticleConfig pc)
{
  pc.resolveDefaults(c);
  return pc;
}

inline ParticleRecord sphere(std::int64_t id, Vec3 x, double radius, double density, Vec3 v = {}, Vec3 w = {})
{
  ParticleRecord r;
  r.id = id;
  r.x = x;
  r.radius = radius;
  r.density = density;
  r.v = v;
  r.w = w;
  return r;
}

// A spheroid of equatorial semi-axis a and aspect c/a, its symmetry axis along `axis`.
inline ParticleRecord spheroid(std::int64_t id, Vec3 x, double a, double aspect, Vec3 axis, double density, Vec3 v = {}, Vec3 w = {})
{
  ParticleRecord r = sphere(id, x, a, density, v, w);
  r.aspect.value = aspect;
  r.q = alignedWith(axis / norm(axis));
  return r;
}

// The owned particles of all ranks, on every rank, sorted by id.
struct State {
  std::int64_t id;
  Vec3 x, v, w;
};

inline std::vector<State> gatherState(MPI_Comm comm, const ParticleStore& s)
{
  std::vector<State> mine;
  for (std::size_t i = 0; i < s.nOwned; ++i) mine.push_back({s.id[i], s.x[i], s.v[i], s.w[i]});
  int size, n = static_cast<int>(mine.size() * sizeof(State));
  MPI_Comm_size(comm, &size);
  std::vector<int> counts(size), displs(size);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<State> all(total / sizeof(State));
  MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, comm);
  std::sort(all.begin(), all.end(), [](const State& a, const State& b) { return a.id < b.id; });
  return all;
}

inline bool bitwiseEqual(const std::vector<State>& a, const std::vector<State>& b)
{
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id) return false;
    for (int d = 0; d < 3; ++d)
      if (a[i].x[d] != b[i].x[d] || a[i].v[d] != b[i].v[d] || a[i].w[d] != b[i].w[d]) return false;
  }
  return true;
}

// True on every rank if the condition holds on every rank (avoids a REQUIRE failing on one rank only).
inline bool allRanks(MPI_Comm comm, bool ok)
{
  int local = ok ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, comm);
  return global == 1;
}

} // namespace vp::test
