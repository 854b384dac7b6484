#include "vp/interactions/LubricationModel.hpp"
#include "vp/core/Error.hpp"
#include "vp/interactions/Blcm.hpp"
#include "vp/interactions/Llcm.hpp"
#include <algorithm>
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

void LubricationParams::complete(double activationFromGrid, double saturationFromRoughness)
{
  if (activation == 0) activation = activationFromGrid;
  if (saturation == 0) saturation = saturationFromRoughness;
  if (model == LubModel::None) return;
  std::ostringstream msg;
  if (!(activation > 0 && std::isfinite(activation)))
    msg << "option -lub_activation: must be > 0 (gap over radius), got " << activation;
  else if (!(saturation > 0 && saturation < activation))
    msg << "option -lub_saturation: must be in (0, -lub_activation = " << activation << "), got " << saturation;
  else if (!(llcmRegion > 0 && std::isfinite(llcmRegion)))
    msg << "option -lub_llcm_r0: must be > 0, got " << llcmRegion;
  if (!msg.str().empty()) throw InputError(msg.str());
}

PairForce lubricationModelForce(LubModel model, double llcmRegion, const PairState& s)
{
  switch (model) {
  case LubModel::Blcm: return blcmForce(s);
  case LubModel::Llcm: return llcmForce(s, llcmRegion);
  default: return {};
  }
}

PairForce lubricationForce(const LubricationParams& p, const PairState& s)
{
  const double a = std::min(s.radiusI, s.radiusJ);
  const double hAct = p.activation * a;
  if (p.model == LubModel::None || !(s.gap < hAct)) return {};

  PairState at = s, act = s;
  at.gap = std::max(s.gap, p.saturation * a);
  act.gap = hAct;
  PairForce f = lubricationModelForce(p.model, p.llcmRegion, at);
  f -= lubricationModelForce(p.model, p.llcmRegion, act);

  const Vec3 midGapMoment = cross(0.5 * s.gap * s.normal, f.forceI);
  f.torqueI += midGapMoment;
  if (!s.isWall()) f.torqueJ += midGapMoment;
  return f;
}

} // namespace vp
