#pragma once
// Lubrication correction for a pair loop: model choice, activation and saturation.
// Only the part the grid does not resolve is applied (PHYSICS.md 4.3):
//   F_lub(h) = F_model(max(h, h_sat)) - F_model(h_act)  for h < h_act,  0 otherwise,
// with h_act = activation * a and h_sat = saturation * a, a = min(a_i, a_j) (a_i at a wall).
// The same subtraction applies to the torques; then both torques get (h/2) n x F_i (the force acts
// at mid-gap), so T_i + T_j = |x_j - x_i| n x F_i holds exactly at every gap.
#include "vp/interactions/Lubrication.hpp"

namespace vp {

enum class LubModel { None, Blcm, Llcm };
const char* lubModelName(LubModel m);

struct LubricationParams {
  LubModel model = LubModel::None;
  // eps_act = h_act / a. 0 means "set by the caller": from the grid spacing in coupled runs
  // (about one to two cells), required explicitly in DEM-only runs.
  double activation = 0;
  // eps_sat = h_sat / a: the force is held constant below it. 0 means "set by the caller" to the
  // contact roughness gap (2 * -contact_roughness, which is a fraction of the diameter).
  double saturation = 0;
  double llcmRegion = 1; // R0 = r0 / R, radius of the LLCM lubrication region in reduced radii

  // Sets the caller-supplied defaults where the options left 0 and checks the complete set
  // (throws InputError naming the option).
  void complete(double activationFromGrid, double saturationFromRoughness);
};

// Raw model force at the state's gap (no activation or saturation).
PairForce lubricationModelForce(LubModel model, double llcmRegion, const PairState& s);

// The correction a pair loop adds for a sphere-sphere or sphere-wall pair. Needs activation > 0
// and 0 < saturation < activation (see complete()).
PairForce lubricationForce(const LubricationParams& p, const PairState& s);

} // namespace vp
