#include "vp/interactions/ContactOptions.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <cmath>
#include <string>

namespace vp {

const char* contactHydroName(ContactHydro h)
{
  switch (h) {
  case ContactHydro::Exclude: return "exclude";
  case ContactHydro::Limit: return "limit";
  default: return "keep";
  }
}

ContactConfig readContactOptions()
{
  ContactConfig k;
  OptionGroup o("Contact model: linear spring-dashpot + tangential spring + Coulomb");
  k.restitution = o.real("-contact_restitution", k.restitution, "Normal restitution coefficient (dry), in (0, 1]");
  k.restitutionT = o.real("-contact_restitution_t", k.restitutionT, "Tangential restitution of a sticking contact, in (0, 1] "
                                                                     "(0: from -contact_kt_ratio and -contact_damping_t_ratio)");
  k.friction = o.real("-contact_friction", k.friction, "Coulomb friction coefficient (sphere-sphere and sphere-wall)");
  k.tc = o.real("-contact_tc", k.tc, "Contact duration (s); stiffness scales with the pair mass "
                                      "(none of -contact_tc, _tc_steps, _kn: 10 fluid steps)");
  k.tcSteps = o.real("-contact_tc_steps", k.tcSteps, "Contact duration in fluid time steps (needs -time_dt)");
  k.kn = o.real("-contact_kn", k.kn, "Sphere-sphere normal stiffness (N/m), instead of -contact_tc");
  k.knWall = o.real("-contact_kn_wall", k.knWall, "Sphere-wall normal stiffness (N/m); 0: -contact_kn");
  k.ktRatio = o.real("-contact_kt_ratio", k.ktRatio, "Tangential / normal stiffness k_t/k_n (without -contact_restitution_t)");
  k.gtRatio = o.real("-contact_damping_t_ratio", k.gtRatio, "Tangential / normal damping gamma_t/gamma_n (without -contact_restitution_t)");
  k.roughness = o.real("-contact_roughness", k.roughness, "Surface gap at which contact starts, fraction of the (mean) diameter");
  k.criticalLoad = o.real("-contact_critical_load", k.criticalLoad,
                          "Critical load model (N): Coulomb friction acts only on contacts whose normal force exceeds it, "
                          "frictionless below (0: always; stress scale sigma* = F_CL / (6 pi a^2), docs/rheology.md)");
  k.rollingFriction = o.real("-contact_rolling_friction", k.rollingFriction,
                             "Rolling resistance mu_r: a torque mu_r R* k_n delta against the relative rolling (0: none)");
  k.hydro = static_cast<ContactHydro>(o.choice("-contact_hydro", {"keep", "exclude", "limit"}, static_cast<int>(k.hydro),
                                               "Resolved hydrodynamic force during contact: keep, exclude (buoyancy stays), "
                                               "limit (excluded beyond the buoyant-weight overlap)"));
  k.departureCells = o.real("-contact_hydro_departure", k.departureCells,
                            "With -contact_hydro limit: a sphere leaving a wall or another sphere after an impact keeps its resolved force "
                            "excluded and gets the lubrication correction from this gap, in grid cells, until it is "
                            "that far (0: off; the collision cases use 1; docs/collisions.md)");
  k.hydroHistory = o.flag("-contact_hydro_history", k.hydroHistory,
                          "With -contact_hydro_departure: while the resolved force is excluded, the Basset history force of the "
                          "particle's velocity changes since it was excluded acts instead, out of contact (docs/collisions.md)");
  return k;
}

void ContactConfig::validate() const
{
  if (!(restitution > 0 && restitution <= 1)) failOption("-contact_restitution", "must be in (0, 1]", restitution);
  if (!(restitutionT >= 0 && restitutionT <= 1)) failOption("-contact_restitution_t", "must be in (0, 1] (0: not set)", restitutionT);
  if (!(friction >= 0) || !std::isfinite(friction)) failOption("-contact_friction", "must be >= 0", friction);
  if (!(tc >= 0) || !std::isfinite(tc)) failOption("-contact_tc", "must be > 0 (s)", tc);
  if (!(tcSteps >= 0) || !std::isfinite(tcSteps)) failOption("-contact_tc_steps", "must be > 0", tcSteps);
  if (!(kn >= 0) || !std::isfinite(kn)) failOption("-contact_kn", "must be > 0 (N/m)", kn);
  if (!(knWall >= 0) || !std::isfinite(knWall)) failOption("-contact_kn_wall", "must be > 0 (N/m)", knWall);
  const int laws = (tc > 0) + (tcSteps > 0) + (kn > 0);
  if (laws > 1) failOption("-contact_tc", "give only one of -contact_tc, -contact_tc_steps, -contact_kn");
  if (knWall > 0 && !(kn > 0)) failOption("-contact_kn_wall", "needs -contact_kn");
  if (!(ktRatio >= 0 && ktRatio <= 1)) failOption("-contact_kt_ratio", "must be in [0, 1]", ktRatio);
  if (!(gtRatio >= 0 && gtRatio <= 1)) failOption("-contact_damping_t_ratio", "must be in [0, 1]", gtRatio);
  if (!(roughness >= 0 && roughness < 0.5)) failOption("-contact_roughness", "must be in [0, 0.5)", roughness);
  if (!(rollingFriction >= 0 && rollingFriction <= 1)) failOption("-contact_rolling_friction", "must be in [0, 1]", rollingFriction);
  if (!(criticalLoad >= 0) || !std::isfinite(criticalLoad))
    failOption("-contact_critical_load", "must be >= 0 (N; 0: friction on every contact)", criticalLoad);
  if (!(departureCells >= 0 && departureCells <= 4)) failOption("-contact_hydro_departure", "must be in [0, 4] grid cells", departureCells);
  if (hydroHistory && !(departureCells > 0))
    failOption("-contact_hydro_history", "needs -contact_hydro_departure (the force acts out of contact, while a sphere departs)");
  if (departureCells > 0 && hydro != ContactHydro::Limit)
    failOption("-contact_hydro_departure", std::string("needs -contact_hydro limit (given: ") + contactHydroName(hydro) + ")");
}

} // namespace vp
