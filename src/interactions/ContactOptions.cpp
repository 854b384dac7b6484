#include "vp/interactions/ContactOptions.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <petscsys.h>
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

namespace {

PetscErrorCode registerOptions(MPI_Comm comm, ContactConfig& k, char* hydro, size_t len)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Contact model: linear spring-dashpot + tangential spring + Coulomb", "vpsolve");
  PetscCall(PetscOptionsReal("-contact_restitution", "Normal restitution coefficient (dry), in (0, 1]", "", k.restitution, &k.restitution, nullptr));
  PetscCall(PetscOptionsReal("-contact_restitution_t", "Tangential restitution of a sticking contact, in (0, 1] (0: from -contact_kt_ratio and -contact_damping_t_ratio)", "", k.restitutionT, &k.restitutionT, nullptr));
  PetscCall(PetscOptionsReal("-contact_friction", "Coulomb friction coefficient (sphere-sphere and sphere-wall)", "", k.friction, &k.friction, nullptr));
  PetscCall(PetscOptionsReal("-contact_tc", "Contact duration (s); stiffness scales with the pair mass", "", k.tc, &k.tc, nullptr));
  PetscCall(PetscOptionsReal("-contact_tc_steps", "Contact duration in fluid time steps (needs -time_dt)", "", k.tcSteps, &k.tcSteps, nullptr));
  PetscCall(PetscOptionsReal("-contact_kn", "Sphere-sphere normal stiffness (N/m), instead of -contact_tc", "", k.kn, &k.kn, nullptr));
  PetscCall(PetscOptionsReal("-contact_kn_wall", "Sphere-wall normal stiffness (N/m); 0: -contact_kn", "", k.knWall, &k.knWall, nullptr));
  PetscCall(PetscOptionsReal("-contact_kt_ratio", "Tangential / normal stiffness k_t/k_n (without -contact_restitution_t)", "", k.ktRatio, &k.ktRatio, nullptr));
  PetscCall(PetscOptionsReal("-contact_damping_t_ratio", "Tangential / normal damping gamma_t/gamma_n (without -contact_restitution_t)", "", k.gtRatio, &k.gtRatio, nullptr));
  PetscCall(PetscOptionsReal("-contact_roughness", "Surface gap at which contact starts, fraction of the (mean) diameter", "", k.roughness, &k.roughness, nullptr));
  PetscCall(PetscOptionsString("-contact_hydro", "Resolved hydrodynamic force during contact: keep, exclude (buoyancy stays), limit (excluded beyond the buoyant-weight overlap)", "", hydro, hydro, len, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

} // namespace

ContactConfig readContactOptions(MPI_Comm comm)
{
  ContactConfig k;
  char hydro[32];
  std::snprintf(hydro, sizeof hydro, "%s", contactHydroName(k.hydro));
  VP_CALL(registerOptions(comm, k, hydro, sizeof hydro));
  const std::string h = hydro;
  if (h == "keep") k.hydro = ContactHydro::Keep;
  else if (h == "exclude") k.hydro = ContactHydro::Exclude;
  else if (h == "limit") k.hydro = ContactHydro::Limit;
  else failOption("-contact_hydro", "unknown value '" + h + "' (valid: keep, exclude, limit)");
  return k;
}

void ContactConfig::validate(bool particles) const
{
  auto fail = [](const char* option, const std::string& what, double got) {
    failOption(option, what + ", got " + formatNumber(got));
  };
  if (!(restitution > 0 && restitution <= 1)) fail("-contact_restitution", "must be in (0, 1]", restitution);
  if (!(restitutionT >= 0 && restitutionT <= 1)) fail("-contact_restitution_t", "must be in (0, 1] (0: not set)", restitutionT);
  if (!(friction >= 0) || !std::isfinite(friction)) fail("-contact_friction", "must be >= 0", friction);
  if (!(tc >= 0) || !std::isfinite(tc)) fail("-contact_tc", "must be > 0 (s)", tc);
  if (!(tcSteps >= 0) || !std::isfinite(tcSteps)) fail("-contact_tc_steps", "must be > 0", tcSteps);
  if (!(kn >= 0) || !std::isfinite(kn)) fail("-contact_kn", "must be > 0 (N/m)", kn);
  if (!(knWall >= 0) || !std::isfinite(knWall)) fail("-contact_kn_wall", "must be > 0 (N/m)", knWall);
  const int laws = (tc > 0) + (tcSteps > 0) + (kn > 0);
  if (laws > 1) failOption("-contact_tc", "give only one of -contact_tc, -contact_tc_steps, -contact_kn");
  if (particles && laws == 0)
    failOption("-contact_tc", "particles need a contact stiffness: set -contact_tc, -contact_tc_steps or -contact_kn");
  if (knWall > 0 && !(kn > 0)) failOption("-contact_kn_wall", "needs -contact_kn");
  if (!(ktRatio >= 0 && ktRatio <= 1)) fail("-contact_kt_ratio", "must be in [0, 1]", ktRatio);
  if (!(gtRatio >= 0 && gtRatio <= 1)) fail("-contact_damping_t_ratio", "must be in [0, 1]", gtRatio);
  if (!(roughness >= 0 && roughness < 0.5)) fail("-contact_roughness", "must be in [0, 0.5)", roughness);
}

} // namespace vp
