#pragma once
// Volume penalization of the particles (docs/coupling.md): a mask chi in [0, 1] and the solid
// velocity u_s = U + Omega x r on every owned velocity face, built from owned and ghost particles.
// The term chi lambda (u_s - u) is applied implicitly inside the predictor's viscous solve
// (Projection::predict with theta = chi lambda dt), before the projection; see docs/coupling.md for
// why not after it.
// Mask (-penalization_mask): smooth (default) = smoothed Heaviside of the signed distance
// a - |x - X| over -penalization_width cells centred on the surface (a face's chi varies smoothly
// as a sphere moves, so forces do not jump when faces change sides); sharp = 1 inside, 0 outside.
#include "vp/core/Config.hpp"
#include "vp/coupling/LubricationPatches.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/particles/PairStress.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <vector>

namespace vp {

struct PenalizationConfig {
  enum class Mask { Smooth, Sharp } mask = Mask::Smooth;
  double lambda = 0;  // [1/s]; 0: max(400 nu / h^2, the motion's floor), set per step by build()
  double width = 1;   // smoothing width in cells
  bool weightedProjection = false;  // -penalization_projection weighted (Projection.hpp)

  static PenalizationConfig read();  // -penalization_*
  void validate() const;             // throws InputError
};

// Per particle (local index, owned and ghost), the sums one fluid step contributes:
// [0..2] force on the particle from the penalization, [3..5] its torque about the centre,
// [6..8] momentum of the fluid inside (chi-weighted), [9..11] its angular momentum.
constexpr int kHydroSums = 12;

class Penalization {
public:
  Penalization(const Grid& grid, const PenalizationConfig& cfg, double rho, double nu);
  ~Penalization();
  Penalization(const Penalization&) = delete;
  Penalization& operator=(const Penalization&) = delete;

  // Distance beyond a sphere's radius where its mask is non-zero [m].
  double support() const { return support_; }

  // chi, u_s, theta = chi lambda dt and theta u_s at the owned faces from the particles' x, v, w
  // (owned and ghost). theta is zero on faces fixed by a wall. lambdaFloor [1/s]: the least lambda
  // when no -penalization_lambda is given, set by the fastest motion so far (Simulation::buildMask).
  void build(const ParticleStore& s, double dt, double lambdaFloor);
  double lambda() const { return stepLambda_; }  // of the step last built
  // sums (kHydroSums per particle) resized and zeroed, then the force and torque of the
  // penalization on each particle, rho chi lambda (u* - u_s) dV, from the predicted velocity u*.
  // patches (-lub_coupling replace): the normal part of the force on the faces in a particle's gap
  // patches is left out (not its torque).
  void forces(const ParticleStore& s, Vec uStar, std::vector<double>& sums, const LubricationPatches* patches = nullptr);
  // From enableStresslets on, forces() also sums the first moment of the force density on the
  // particles whose centre lies in lo <= z <= hi: sum over them of the integral of
  // sym((x - x_p) (x) f) dV, f the force density the fluid exerts on them (the particles' stresslet,
  // docs/rheology.md). takeStresslets: this rank's mean over the steps since the last take, then zero.
  void enableStresslets(double zlo, double zhi);
  SymTensor takeStresslets();
  // Adds the momentum and angular momentum of the fluid inside each particle (chi-weighted) to sums.
  void addFluidMomentum(const ParticleStore& s, Vec u, std::vector<double>& sums) const;

  Vec chi() const { return chi_; }  // faceDM global vectors
  Vec theta() const { return theta_; }
  Vec thetaUs() const { return thetaUs_; }

private:
  template <class F>
  void forCovered(const ParticleStore& s, F&& f) const;

  const Grid& grid_;
  PenalizationConfig cfg_;
  double rho_, gridLambda_, support_;
  double stepLambda_ = 0;  // lambda of the step being built (build())
  Vec chi_ = nullptr, us_ = nullptr, theta_ = nullptr, thetaUs_ = nullptr;
  std::vector<int> owner_;  // per owned face (3 per cell): particle with the largest chi, or -1
  std::vector<PetscInt> covered_;  // the owned faces with an owner, in increasing order
  bool stresslets_ = false;
  double stressletLo_ = 0, stressletHi_ = 0;
  SymTensor stressletSum_{};  // since the last take
  long stressletSteps_ = 0;
};

} // namespace vp
