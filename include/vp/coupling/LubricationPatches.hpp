#pragma once
// The gap patches of the local lubrication coupling (-lub_coupling replace, after the seed's LLCM:
// the resolved surface forces over the gap are replaced by the analytic inner force). At the start
// of every fluid step, each pair of spheres and each sphere and wall closer than the activation gap
// h_act plus the blend (-lub_patch_blend) gives both its surfaces a patch of weight w (1 below h_act,
// falling linearly to 0 across the blend): the disk r < r0 around the line of centres, on the side
// facing the gap, where the gap is below h + delta (r0^2 = 2 R delta, R the reduced radius, a at a
// wall; delta = -lub_patch_gap times the smaller radius). The fraction w of the normal part (along
// the line of centres) of the penalization force on the faces a sphere owns within its patches'
// cylinders leaves its resolved force, not its torque (Penalization::forces; the moment carries the
// pressure of the tangential motions), and the DEM gives those pairs w times the whole lubrication
// squeeze over the disk for the whole step, whatever their gap during it (LubricationModel.hpp). The tangential
// terms stay resolved, with the added correction below their own activation gap (replaced too,
// they fell 22-33 % short of the exact sliding resistance at d/dx 12: docs/lubrication.md). Found
// from the positions every rank holds, owned and ghost spheres alike: every rank that holds faces
// of a sphere or computes one of its pairs agrees on its patches.
#include "vp/interactions/LubricationModel.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/ParticleStore.hpp"
#include "vp/particles/Walls.hpp"
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace vp {

class LubricationPatches {
public:
  LubricationPatches(const LubricationParams& lub, const std::array<Wall, 6>& walls) : lub_(lub), walls_(walls) {}

  // The patches of the particles' present positions (local spheres, owned and ghost).
  void find(const ParticleStore& s);
  struct Patch {
    std::size_t particle;
    Vec3 n;            // unit, from the centre towards the gap
    double r0Squared;  // [m^2]
    double weight;     // the replaced fraction of the normal force
  };
  // The patch whose cylinder holds the point r (from local sphere p's centre), or null.
  const Patch* patchAt(std::size_t p, const Vec3& r) const
  {
    for (std::size_t k = begin_[p]; k < begin_[p + 1]; ++k) {
      const double along = dot(r, patches_[k].n);
      if (along > 0 && dot(r, r) - along * along < patches_[k].r0Squared) return &patches_[k];
    }
    return nullptr;
  }
  bool any(std::size_t p) const { return begin_[p] < begin_[p + 1]; }
  // The weight with which the pair of these ids (a wall as -1 - face) had its patches taken out at
  // the step's start (0: not).
  double replaced(std::int64_t idI, std::int64_t idJ) const;
  bool replacedAtWall(std::int64_t id) const { return std::binary_search(atWalls_.begin(), atWalls_.end(), id); }
  std::size_t pairs() const { return replaced_.size(); }

private:
  struct Pair {
    std::int64_t lo, hi;  // ids, lower first (a wall's -1 - face sorts first)
    double weight;
    bool operator<(const Pair& o) const { return lo < o.lo || (lo == o.lo && hi < o.hi); }
  };
  LubricationParams lub_;
  std::array<Wall, 6> walls_;
  CellBuckets buckets_;
  std::vector<Patch> patches_;                                   // sorted by particle
  std::vector<std::size_t> begin_{0};                            // per local particle, into patches_
  std::vector<Pair> replaced_;                                   // sorted
  std::vector<std::int64_t> atWalls_;                            // ids with a wall pair replaced, sorted
};

} // namespace vp
