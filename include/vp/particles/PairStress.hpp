#pragma once
// The particles' pair share of a suspension's stress (docs/rheology.md), summed over the DEM
// sub-steps: sum of sym(r_ij (x) F_ij) over the contact pairs and over the lubricated pairs whose
// midpoint lies in a slab lo <= z <= hi (the core of a shear cell; r_ij = x_i - x_j, F_ij the force
// on i), and the force each wall exerts on the particles (contact and lubrication). A fixed particle
// is part of a wall (a rough wall's sphere): its pairs with free particles count as the force of
// the z wall on its side of the slab's midplane, not as pairs. The stress of the pairs is -(1/V)
// times the sum. Off until enable(); a pair counts on the rank that owns its first particle (once
// over all ranks).
#include "vp/core/Vec3.hpp"
#include <array>
#include <mpi.h>

namespace vp {

// xx, yy, zz, xy, xz, yz
using SymTensor = std::array<double, 6>;

// sym(a (x) b)
SymTensor symmetricProduct(const Vec3& a, const Vec3& b);

class PairStress {
public:
  enum Kind { Contact = 0, Lubrication = 1 };

  void enable(double zlo, double zhi)
  {
    on_ = true;
    lo_ = zlo;
    hi_ = zhi;
  }
  bool on() const { return on_; }
  // The z wall face (4: zlo, 5: zhi) a fixed particle at height z belongs to.
  int wallOf(double z) const { return z < 0.5 * (lo_ + hi_) ? 4 : 5; }
  // A pair: x_i, d = x_i - x_j (image), F on i; fixedI, fixedJ: whether i, j are fixed.
  void addPair(Kind k, const Vec3& xi, const Vec3& d, const Vec3& force, bool fixedI, bool fixedJ);
  // The force of wall face f (0..5: xlo, xhi, ylo, ...) on a particle.
  void addWall(Kind k, int face, const Vec3& force) { wall_[k][face] += force; }
  void endSubstep() { ++samples_; }

  // Means over the sub-steps since the last take, summed over the ranks; then zeroed. Collective.
  struct Mean {
    std::array<SymTensor, 2> pairs{};             // [Contact], [Lubrication]
    std::array<std::array<Vec3, 6>, 2> walls{};   // [kind][face]
  };
  Mean take(MPI_Comm comm);

private:
  bool on_ = false;
  double lo_ = 0, hi_ = 0;
  long samples_ = 0;
  std::array<SymTensor, 2> pairs_{};
  std::array<std::array<Vec3, 6>, 2> wall_{};
};

} // namespace vp
