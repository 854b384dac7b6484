#include "vp/particles/PairStress.hpp"
#include <algorithm>

namespace vp {

SymTensor symmetricProduct(const Vec3& a, const Vec3& b)
{
  return {a.x * b.x, a.y * b.y, a.z * b.z, 0.5 * (a.x * b.y + a.y * b.x), 0.5 * (a.x * b.z + a.z * b.x),
          0.5 * (a.y * b.z + a.z * b.y)};
}

void PairStress::addPair(Kind k, const Vec3& xi, const Vec3& d, const Vec3& force, bool fixedI, bool fixedJ)
{
  if (fixedI != fixedJ) {
    // The wall's force on the free particle.
    if (fixedI)
      addWall(k, wallOf(xi.z), -force);
    else
      addWall(k, wallOf(xi.z - d.z), force);
    return;
  }
  const double mid = xi.z - 0.5 * d.z;
  if (mid < lo_ || mid > hi_) return;
  const SymTensor t = symmetricProduct(d, force);
  for (int m = 0; m < 6; ++m) pairs_[k][m] += t[m];
}

PairStress::Mean PairStress::take(MPI_Comm comm)
{
  // 12 pair components and 36 wall components (the sample count is the same on every rank).
  double buf[48];
  for (int k = 0; k < 2; ++k) {
    std::copy(pairs_[k].begin(), pairs_[k].end(), buf + 6 * k);
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) buf[12 + 18 * k + 3 * f + c] = wall_[k][f][c];
  }
  MPI_Allreduce(MPI_IN_PLACE, buf, 48, MPI_DOUBLE, MPI_SUM, comm);
  const double n = std::max<long>(samples_, 1);
  Mean m;
  for (int k = 0; k < 2; ++k) {
    for (int c = 0; c < 6; ++c) m.pairs[k][c] = buf[6 * k + c] / n;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) m.walls[k][f][c] = buf[12 + 18 * k + 3 * f + c] / n;
  }
  pairs_ = {};
  wall_ = {};
  samples_ = 0;
  return m;
}

} // namespace vp
