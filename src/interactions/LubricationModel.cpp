#include "vp/interactions/LubricationModel.hpp"
#include "vp/core/Error.hpp"
#include "vp/interactions/Blcm.hpp"
#include "vp/interactions/Llcm.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace vp {

const char* lubModelName(LubModel m)
{
  switch (m) {
  case LubModel::Blcm: return "blcm";
  case LubModel::Llcm: return "llcm";
  default: return "none";
  }
}

void LubricationParams::resolveDefaults(double cellSize, bool coupled, double saturationFromRoughness)
{
  // The resolved squeeze follows the exact Stokes resistance down to gaps of a fraction of a cell
  // (docs/collisions_calibration.md): the correction starts there.
  if (activation == 0 && activationCells == 0 && coupled)
    activationCells = replace ? kDefaultReplacementCells : kDefaultActivationCells;
  // The resolved shear force and torque follow theirs to smaller gaps still (same page).
  if (shearActivationCells == 0) shearActivationCells = std::min(activationCells, kDefaultShearActivationCells);
  gridGap_ = activationCells * cellSize;
  shearGridGap_ = shearActivationCells * cellSize;
  blendGap_ = patchBlendCells * cellSize;
  if (saturation == 0) saturation = saturationFromRoughness > 0 ? saturationFromRoughness : kDefaultSaturation;
  resolved_ = true;
  if (model == LubModel::None) return;
  std::ostringstream msg;
  if (!(activation > 0 || activationCells > 0))
    msg << "option -lub_activation: must be > 0 (gap over radius), got " << activation
        << " (DEM-only runs set -lub_activation or -lub_activation_cells)";
  else if (!(saturation > 0 && saturation < activation) && activation > 0)
    msg << "option -lub_saturation: must be in (0, -lub_activation = " << activation << "), got " << saturation;
  else if (activation == 0 && !(saturation > 0))
    msg << "option -lub_saturation: must be > 0, got " << saturation;
  else if (activation == 0 && !(shearActivationCells > 0 && shearActivationCells <= activationCells))
    msg << "option -lub_shear_activation_cells: must be in (0, -lub_activation_cells = " << activationCells
        << "], got " << shearActivationCells;
  else if (!(llcmRegion > 0 && std::isfinite(llcmRegion)))
    msg << "option -lub_llcm_r0: must be > 0, got " << llcmRegion;
  else if (replace && !coupled)
    msg << "option -lub_coupling: replace takes the gap patch out of the resolved force: it needs a fluid (drop -fluid_off "
           "or use add)";
  if (!msg.str().empty()) throw InputError(msg.str());
}

void LubricationParams::checkRadius(double rmax) const
{
  if (model == LubModel::None || activation > 0 || saturation * rmax < gridGap_) return;
  std::ostringstream msg;
  msg << "option -lub_saturation: the saturation gap " << saturation << " a must be below the activation gap "
      << "-lub_activation_cells = " << activationCells << " cells (" << gridGap_ << " m) for the largest radius "
      << rmax << " m, got " << saturation;
  throw InputError(msg.str());
}

PairForce lubricationModelForce(LubModel model, double llcmRegion, const PairState& s, bool patch, LubPart part)
{
  switch (model) {
  case LubModel::Blcm: return part == LubPart::Shear ? PairForce{} : blcmForce(s);  // a squeeze only
  case LubModel::Llcm: return llcmForce(s, llcmRegion, patch, part);
  default: return {};
  }
}

namespace {

// F_model(max(h, h_sat)) - F_model(h_act) of one part of the motion (the state carries that part's
// velocities only) below h_act; a pair replaced with weight w: w times the first term over its patch
// (r0^2 = 2 R delta: the region R0 = r0 / R) and 1 - w times the former.
PairForce unresolvedPart(const LubricationParams& p, const PairState& s, LubPart part, double hAct, double a, double w)
{
  PairState at = s, act = s;
  at.gap = std::max(s.gap, p.saturation * a);
  act.gap = hAct;
  PairForce f;
  if (w < 1 && s.gap < hAct) {
    f = lubricationModelForce(p.model, p.llcmRegion, at, false, part);
    f -= lubricationModelForce(p.model, p.llcmRegion, act, false, part);
    f *= 1 - w;
  }
  if (w > 0) {
    const double R = s.reducedRadius();
    PairForce patch = lubricationModelForce(p.model, std::sqrt(p.patchRadiusSquared(R, a)) / R, at, true, part);
    patch *= w;
    f += patch;
  }
  return f;
}

} // namespace

PairForce lubricationForce(const LubricationParams& p, const PairState& s, double contactGap, double scale, double replaced)
{
  const double a = scale > 0 ? scale : std::min(s.radiusI, s.radiusJ);
  const double hAct = p.activationGap(a);
  if (p.model == LubModel::None || !(s.gap < hAct || replaced > 0) || s.gap <= contactGap) return {};

  // The squeeze: the normal relative motion alone.
  PairState squeeze = s;
  squeeze.velocityI = dot(s.velocityI, s.normal) * s.normal;
  squeeze.velocityJ = dot(s.velocityJ, s.normal) * s.normal;
  squeeze.angularVelocityI = squeeze.angularVelocityJ = Vec3{};
  PairForce f = unresolvedPart(p, squeeze, LubPart::Squeeze, hAct, a, replaced);
  if (s.slipWall) {
    // One shear-free surface: the gap flow is a half Poiseuille profile, four times the flux per
    // pressure gradient, so a quarter of the squeeze pressure; no Couette shear to resist sliding.
    return {0.25 * dot(f.forceI, s.normal) * s.normal, {}, {}};
  }
  if (p.inertia && s.isWall() && s.density > 0) {
    // The liquid's inertia in the squeeze film, first order in Re (docs/lubrication.md): the pressure
    // rho U^2 a (3/(10 h) + 27 h_0/(70 h^2)) of the film h = h_0 + r^2/(2a) has the force
    // 2 pi rho U^2 a^2 ((3/10) ln(H/h_0) + const); below h_act the grid misses its logarithm.
    const double U = dot(s.velocityI - s.velocityJ, s.normal);
    const double h = std::max(s.gap, p.saturation * a);
    f.forceI -= (0.6 * M_PI * s.density * a * a * U * U * std::log(hAct / h)) * s.normal;
  }
  const double hShear = p.shearActivationGap(a);
  if (s.gap < hShear && p.saturation * a < hShear) {
    PairState shear = s;
    shear.velocityI = s.tangential(s.velocityI);
    shear.velocityJ = s.tangential(s.velocityJ);
    f += unresolvedPart(p, shear, LubPart::Shear, hShear, a, 0);
  }
  const Vec3 midGapMoment = cross(0.5 * s.gap * s.normal, f.forceI);
  f.torqueI += midGapMoment;
  if (!s.isWall()) f.torqueJ += midGapMoment;
  return f;
}

double lubricationResistance(const LubricationParams& p, const PairState& geometry, double contactGap)
{
  PairState s = geometry;
  const double a = std::min(s.radiusI, s.radiusJ);
  s.gap = std::max(p.saturation * a, contactGap * (1 + 1e-12));
  return squeezeResistance(p, s, contactGap, p.replace ? 1 : 0);  // a replaced pair's whole force is the larger
}

double squeezeResistance(const LubricationParams& p, const PairState& state, double contactGap, double replaced)
{
  PairState s = state;
  s.velocityI = s.normal;  // unit approach speed
  s.velocityJ = s.angularVelocityI = s.angularVelocityJ = Vec3{};
  s.density = 0;  // the resistance of the viscous squeeze alone
  return std::fabs(dot(lubricationForce(p, s, contactGap, 0, replaced).forceI, s.normal));
}

} // namespace vp
