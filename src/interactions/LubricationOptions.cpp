#include "vp/interactions/LubricationOptions.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <cmath>
#include <sstream>
#include <string>

namespace vp {

LubricationParams readLubricationOptions()
{
  LubricationParams p;
  OptionGroup o("Lubrication correction (gaps as fractions of the radius)");
  p.model = static_cast<LubModel>(o.choice("-lub_model", {"none", "blcm", "llcm"}, 0, "Lubrication model"));
  p.activation = o.real("-lub_activation", p.activation, "Gap eps_act = h/a (a: the smaller radius of the pair) below which "
                                                         "the unresolved force is added (0: -lub_activation_cells)");
  p.activationCells = o.real("-lub_activation_cells", p.activationCells,
                             "Activation gap in grid cells, the same for every pair (0: 0.18 in coupled runs, 1 with -lub_coupling replace)");
  p.shearActivationCells = o.real("-lub_shear_activation_cells", p.shearActivationCells,
                                  "Activation gap of the tangential (sliding, rolling) terms in grid cells "
                                  "(0: 0.06 in coupled runs, at most -lub_activation_cells)");
  p.saturation = o.real("-lub_saturation", p.saturation, "Gap eps_sat = h/a below which the force is held constant "
                                                         "(0: the contact roughness, or 4e-4 without one)");
  p.llcmRegion = o.real("-lub_llcm_r0", p.llcmRegion,
                        "LLCM lubrication-region radius r0 in units of the reduced radius (<= 1 keeps the parabolic gap valid)");
  p.implicitSqueeze = o.choice("-lub_integration", {"explicit", "implicit"}, 0,
                               "Normal (squeeze) lubrication in the DEM sub-steps: explicit (stable below the smallest gap's "
                               "relaxation time m* / c), or implicit in each sphere's own velocity (stable at any sub-step; "
                               "docs/lubrication.md)") == 1;
  p.inertia = o.flag("-lub_inertia", p.inertia,
                     "Add the liquid's inertia in the gap to a sphere's squeeze at a no-slip wall: the O(Re) term "
                     "(3/5) pi rho a^2 U^2 ln(h_act/h) of the lubrication flow, repulsive (Cox & Brenner 1967; "
                     "docs/lubrication.md)");
  p.replace = o.choice("-lub_coupling", {"add", "replace"}, 0,
                       "How the correction meets the resolved force: add (the unresolved part F(h) - F(h_act) on top of the "
                       "whole resolved force) or replace (the seed's local LLCM: below h_act the resolved normal force over "
                       "each gap's patch is removed and the lubrication squeeze over that patch applied; needs -lub_model "
                       "llcm; docs/lubrication.md)") == 1;
  p.patchGap = o.real("-lub_patch_gap", p.patchGap,
                      "With -lub_coupling replace: the patch is the disk where the gap is below h + delta, delta = this "
                      "times the smaller radius (0.2: r0 = 0.45 a between equal spheres, 0.63 a at a wall)");
  p.patchBlendCells = o.real("-lub_patch_blend", p.patchBlendCells,
                             "With -lub_coupling replace: grid cells beyond the activation gap over which the replaced "
                             "fraction of a patch falls linearly from 1 to 0 (0: a sharp switch)");
  if (optionsHelpMode()) return p;
  if (!(p.activation >= 0 && std::isfinite(p.activation)))
    failOption("-lub_activation", "must be >= 0 (0: set from the grid spacing)", p.activation);
  if (!(p.activationCells >= 0 && std::isfinite(p.activationCells)))
    failOption("-lub_activation_cells", "must be >= 0 (0: 0.18 cells in coupled runs)", p.activationCells);
  if (p.activation > 0 && p.activationCells > 0)
    failOption("-lub_activation_cells", "give either -lub_activation or -lub_activation_cells", p.activationCells);
  if (!(p.shearActivationCells >= 0 && std::isfinite(p.shearActivationCells)))
    failOption("-lub_shear_activation_cells", "must be >= 0 (0: 0.06 cells in coupled runs)", p.shearActivationCells);
  if (p.activation > 0 && p.shearActivationCells > 0)
    failOption("-lub_shear_activation_cells", "give it with -lub_activation_cells, not -lub_activation",
               p.shearActivationCells);
  if (!(p.saturation >= 0 && std::isfinite(p.saturation)))
    failOption("-lub_saturation", "must be >= 0 (0: the contact roughness)", p.saturation);
  if (p.activation > 0 && p.saturation >= p.activation) {
    std::ostringstream what;
    what << "must be below -lub_activation (" << p.activation << ")";
    failOption("-lub_saturation", what.str(), p.saturation);
  }
  if (p.implicitSqueeze && p.model == LubModel::None)
    failOption("-lub_integration", "implicit integrates the lubrication's squeeze: it needs -lub_model blcm or llcm");
  if (p.inertia && p.model == LubModel::None)
    failOption("-lub_inertia", "corrects the lubrication's squeeze: it needs -lub_model blcm or llcm");
  if (!(p.llcmRegion > 0 && std::isfinite(p.llcmRegion)))
    failOption("-lub_llcm_r0", "must be > 0", p.llcmRegion);
  if (p.replace && p.model != LubModel::Llcm)
    failOption("-lub_coupling", "replace applies the LLCM's inner solution over the gap's disk r < r0: it needs -lub_model llcm");
  // r0^2 = 2 R delta <= a^2 for every pair (R <= a, a sphere's at a wall) while delta <= a/2.
  if (!(p.patchGap > 0 && p.patchGap <= 0.5))
    failOption("-lub_patch_gap", "must be in (0, 0.5]: the patch (r0^2 = 2 R delta) must fit within the sphere", p.patchGap);
  if (p.patchGap != kDefaultPatchGap && !p.replace) failOption("-lub_patch_gap", "applies to -lub_coupling replace only");
  if (!(p.patchBlendCells >= 0 && p.patchBlendCells <= 4))
    failOption("-lub_patch_blend", "must be in [0, 4] grid cells", p.patchBlendCells);
  if (p.patchBlendCells != kDefaultPatchBlendCells && !p.replace)
    failOption("-lub_patch_blend", "applies to -lub_coupling replace only");
  if (p.replace && p.implicitSqueeze)
    failOption("-lub_integration", "implicit takes the added squeeze; with -lub_coupling replace use explicit");
  if (p.replace && p.inertia)
    failOption("-lub_inertia", "is the film's inertia below h_act added to the resolved force: not with -lub_coupling replace");
  return p;
}

} // namespace vp
