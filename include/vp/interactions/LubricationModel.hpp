#pragma once
// Lubrication correction for a pair loop: model choice, activation and saturation.
// Only the part the grid does not resolve is applied (docs/lubrication.md):
//   F_lub(h) = F_model(max(h, h_sat)) - F_model(h_act)  for h_contact < h < h_act,  0 otherwise,
// with h_act = activation * a (or a fixed gap in grid cells), h_sat = saturation * a,
// a = min(a_i, a_j) (a_i at a wall). The model is linear in the velocities: its squeeze part (the
// normal relative motion) takes h_act, its tangential part (sliding, rolling) the smaller h_act,t,
// since the grid resolves the logarithmic shear singularity to smaller gaps than the squeeze.
// Zero once the surfaces touch (h <= h_contact, the roughness gap): the contact model alone acts
// there. With -lub_coupling replace a pair closer than h_act at the start of a fluid step has the
// resolved normal force over its gap patch removed (coupling/LubricationPatches.hpp) and gets the
// whole squeeze of the lubrication pressure over that disk instead, F_blcm (1 - h/H0) at
// max(h, h_sat), H0 = h + delta (Llcm.hpp, open edge), whatever its gap during the step; from h_act
// to h_act + -lub_patch_blend cells a weight w falling from 1 to 0 replaces that fraction only; its
// tangential terms stay added. A free-slip wall gets a quarter of the squeeze and no
// shear (lubrication with one shear-free surface).
// The same subtraction applies to the torques; then both torques get (h/2) n x F_i (the force acts
// at mid-gap), so T_i + T_j = |x_j - x_i| n x F_i holds exactly at every gap.
#include "vp/interactions/Lubrication.hpp"
#include <algorithm>

namespace vp {

enum class LubModel { None, Blcm, Llcm };

// Default activation gap of coupled runs, in grid cells (calibrated: docs/collisions.md).
constexpr double kDefaultActivationCells = 0.18;
// Default activation gap of -lub_coupling replace, in grid cells: the replaced patches then cover
// the gaps whose squeeze depends on their position on the grid (docs/collisions_calibration.md).
constexpr double kDefaultReplacementCells = 1.0;
// Default depth of a replaced patch, delta / a (measured: docs/collisions_calibration.md).
constexpr double kDefaultPatchGap = 0.2;
// Default width, in grid cells beyond h_act, over which the replacement fades out (measured: same page).
constexpr double kDefaultPatchBlendCells = 3.0;
// Default activation gap of the tangential terms, in grid cells (calibrated: docs/collisions.md).
constexpr double kDefaultShearActivationCells = 0.06;
// Saturation gap eps_sat = h/a when neither -lub_saturation nor a roughness is given: the roughness of
// the calibration spheres, 2e-4 d (docs/lubrication.md).
constexpr double kDefaultSaturation = 4e-4;
const char* lubModelName(LubModel m);

struct LubricationParams {
  LubModel model = LubModel::None;
  // eps_act = h_act / a, per pair radius. 0: the gap activationCells grid cells instead.
  double activation = 0;
  // h_act in grid cells (when activation is 0); 0: set by resolveDefaults() (kDefaultActivationCells
  // in coupled runs, kDefaultReplacementCells with replace).
  double activationCells = 0;
  // h_act,t of the tangential terms in grid cells (with activationCells; 0: set by resolveDefaults() to
  // kDefaultShearActivationCells, at most activationCells). With an activation in radii both parts
  // use that gap.
  double shearActivationCells = 0;
  // eps_sat = h_sat / a: the force is held constant below it. 0 means "set by the caller" to the
  // contact roughness gap (2 * -contact_roughness, which is a fraction of the diameter).
  double saturation = 0;
  double llcmRegion = 1; // R0 = r0 / R, radius of the LLCM lubrication region in reduced radii
  // -lub_integration implicit: the squeeze (normal) part taken implicitly in the DEM sub-steps
  // (DemSolver), so that the sub-step is not bounded by the smallest gap's relaxation time.
  bool implicitSqueeze = false;
  // -lub_inertia: the O(Re) squeeze of a sphere approaching or leaving a no-slip wall (the liquid's
  // inertia in the gap; docs/lubrication.md), from the state's density.
  bool inertia = false;
  // -lub_coupling replace: the seed's local replacement of the resolved force over the gap patch
  // (coupling/LubricationPatches.hpp) instead of the added unresolved part.
  bool replace = false;
  // -lub_patch_gap delta / a: the patch is the disk where the gap is below h + delta,
  // r0^2 = 2 R delta (a: the smaller radius, a sphere's at a wall).
  double patchGap = kDefaultPatchGap;
  double patchRadiusSquared(double R, double a) const { return 2 * R * patchGap * a; }
  // -lub_patch_blend, grid cells: the replacement's weight falls linearly from 1 at h_act to 0 at
  // h_act + this (0: a sharp switch at h_act). Around a cell the resolved squeeze's own error changes
  // sign with the gap, so a sharp switch leaves it whole just above h_act.
  double patchBlendCells = kDefaultPatchBlendCells;

  // Sets the defaults where the options left 0 and checks the set (throws InputError naming the
  // option); called once, by the run's configuration (ParticleConfig::resolveDefaults). coupled: a
  // fluid is solved (the activation then defaults to kDefaultActivationCells; DEM-only runs must
  // give it).
  void resolveDefaults(double cellSize, bool coupled, double saturationFromRoughness);
  bool resolved() const { return resolved_; }
  // The particles' part of the check: with a gap in cells, the saturation gap of the largest
  // sphere (radius rmax) must lie below the activation gap (throws InputError naming the option).
  void checkRadius(double rmax) const;
  // Activation gap h_act [m] of a pair whose smaller radius is a.
  double activationGap(double a) const { return activation > 0 ? activation * a : gridGap_; }
  // Weight of the replacement of a pair at this gap (-lub_coupling replace; 0 without it).
  double replacementWeight(double gap, double a) const
  {
    if (!replace) return 0;
    const double hAct = activationGap(a);
    if (gap < hAct) return 1;
    return blendGap_ > 0 ? std::max(0.0, 1 - (gap - hAct) / blendGap_) : 0;
  }
  // The widest gap [m] at which a pair gets a force: h_act, and the blend's end with replace.
  double reach(double a) const { return activationGap(a) + (replace ? blendGap_ : 0); }
  // Activation gap h_act,t [m] of the tangential terms of that pair.
  double shearActivationGap(double a) const { return activation > 0 ? activation * a : shearGridGap_; }

private:
  double gridGap_ = 0;       // activationCells * cell size [m]
  double shearGridGap_ = 0;  // shearActivationCells * cell size [m]
  double blendGap_ = 0;      // patchBlendCells * cell size [m]
  bool resolved_ = false;
};

// Raw model force at the state's gap (no activation or saturation); patch: the LLCM's open-edge
// squeeze of a replaced gap patch (Llcm.hpp); part: the motions asked for (Lubrication.hpp).
PairForce lubricationModelForce(LubModel model, double llcmRegion, const PairState& s, bool patch = false,
                                LubPart part = LubPart::Both);

// The correction a pair loop adds for a sphere-sphere or sphere-wall pair (defaults resolved).
// contactGap: the surface gap at which the contact model takes over (roughness). scale: the length
// the activation and saturation gaps are fractions of; 0: the smaller radius (a spheroid gives its
// equatorial semi-axis while its radii are those of the gap's curvatures).
// replaced: the weight w of the pair's gap patch taken out of the resolved force at the step's start
// (-lub_coupling replace): w times the whole model squeeze at max(h, h_sat), at any gap, and 1 - w
// times the unresolved part (the tangential terms as without).
PairForce lubricationForce(const LubricationParams& p, const PairState& s, double contactGap, double scale = 0,
                           double replaced = 0);

// Largest normal resistance c = |F_n| / U_n the correction reaches for this pair geometry (at
// max(h_sat, contactGap)); an explicit dashpot c on a reduced mass m is stable for dt < m / c with
// the DEM's integrator (docs/lubrication.md).
double lubricationResistance(const LubricationParams& p, const PairState& geometry, double contactGap);
// The normal resistance c = |F_n| / U_n of the correction at the state's own gap: the squeeze force
// on i is c (dh/dt) n, n from i to j (-lub_integration implicit takes it out of the explicit force).
double squeezeResistance(const LubricationParams& p, const PairState& state, double contactGap, double replaced = 0);

} // namespace vp
