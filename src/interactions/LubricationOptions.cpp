#include "vp/interactions/LubricationOptions.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <petscsys.h>
#include <sstream>
#include <string>

namespace vp {

namespace {

PetscErrorCode registerOptions(MPI_Comm comm, LubricationParams& p, char* model, size_t len)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Lubrication correction (gaps as fractions of the radius)", "vpsolve");
  PetscCall(PetscOptionsString("-lub_model", "Lubrication model: none, blcm, llcm", "", model, model, len, nullptr));
  PetscCall(PetscOptionsReal("-lub_activation",
                             "Gap eps_act = h/a (a: the smaller radius of the pair) below which the unresolved force is added (0: -lub_activation_cells)",
                             "", p.activation, &p.activation, nullptr));
  PetscCall(PetscOptionsReal("-lub_activation_cells",
                             "Activation gap in grid cells, the same for every pair (0: 0.2 in coupled runs)",
                             "", p.activationCells, &p.activationCells, nullptr));
  PetscCall(PetscOptionsReal("-lub_saturation",
                             "Gap eps_sat = h/a below which the force is held constant (0: the contact roughness)",
                             "", p.saturation, &p.saturation, nullptr));
  PetscCall(PetscOptionsReal("-lub_llcm_r0",
                             "LLCM lubrication-region radius r0 in units of the reduced radius (<= 1 keeps the parabolic gap valid)",
                             "", p.llcmRegion, &p.llcmRegion, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

[[noreturn]] void fail(const char* option, const std::string& what, double got)
{
  std::ostringstream msg;
  msg << "option " << option << ": " << what << ", got " << got;
  throw InputError(msg.str());
}

} // namespace

LubricationParams readLubricationOptions(MPI_Comm comm)
{
  LubricationParams p;
  char model[64] = "none";
  VP_CALL(registerOptions(comm, p, model, sizeof model));

  const std::string name = model;
  if (name == "none") p.model = LubModel::None;
  else if (name == "blcm") p.model = LubModel::Blcm;
  else if (name == "llcm") p.model = LubModel::Llcm;
  else throw InputError("option -lub_model: unknown value '" + name + "' (valid: none, blcm, llcm)");

  if (!(p.activation >= 0 && std::isfinite(p.activation)))
    fail("-lub_activation", "must be >= 0 (0: set from the grid spacing)", p.activation);
  if (!(p.activationCells >= 0 && std::isfinite(p.activationCells)))
    fail("-lub_activation_cells", "must be >= 0 (0: 0.2 cells in coupled runs)", p.activationCells);
  if (p.activation > 0 && p.activationCells > 0)
    fail("-lub_activation_cells", "give either -lub_activation or -lub_activation_cells", p.activationCells);
  if (!(p.saturation >= 0 && std::isfinite(p.saturation)))
    fail("-lub_saturation", "must be >= 0 (0: the contact roughness)", p.saturation);
  if (p.activation > 0 && p.saturation >= p.activation) {
    std::ostringstream what;
    what << "must be below -lub_activation (" << p.activation << ")";
    fail("-lub_saturation", what.str(), p.saturation);
  }
  if (!(p.llcmRegion > 0 && std::isfinite(p.llcmRegion)))
    fail("-lub_llcm_r0", "must be > 0", p.llcmRegion);
  return p;
}

} // namespace vp
