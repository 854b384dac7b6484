#include "vp/fluid/SolverOptions.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <string>

namespace vp {

SolverOptions readSolverOptions()
{
  SolverOptions s;
  OptionGroup o("Solvers (any PETSc KSP/PC option with the prefix -pressure_ or -velocity_ also applies)", false);
  s.pressurePc = o.text("-pressure_pc_type", "hypre", "Pressure preconditioner: hypre (BoomerAMG, tuned), fft (exact direct "
                                                      "solve on the uniform grid), pfmg, mg, or another PETSc PC");
  s.pressureKsp = o.text("-pressure_ksp_type", "", "Pressure Krylov method (default cg; preonly with fft)");
  s.pressureGuesses = o.integer("-pressure_guesses", 5, "Earlier pressure solutions (and right-hand sides) from which an iterative "
                                "solve's start is fitted (Fischer's projection; 0: the last solution only)");
  if (!optionsHelpMode() && (s.pressureGuesses < 0 || s.pressureGuesses > 50))
    failOption("-pressure_guesses", "must be in [0, 50], got " + std::to_string(s.pressureGuesses));
  o.real("-pressure_ksp_rtol", 1e-6, "Pressure relative tolerance (measured choice, docs/fluid.md)");
  s.viscousOperator = static_cast<ViscousOperator>(
      o.choice("-velocity_operator", {"fused", "shell", "assembled"}, 0,
               "Viscous operator and solver: fused (matrix-free sweep in a hand-fused CG + Jacobi, fastest), shell "
               "(the same operator under PETSc's KSP: any -velocity_ksp/pc option that needs only products and the "
               "diagonal, monitors) or assembled (AIJ, for preconditioners that need a matrix: hypre, gamg)"));
  s.viscousMgLevels = o.integer("-velocity_mg_levels", 1, "Grids of the geometric multigrid V-cycle that preconditions the fused "
                                "viscous CG (1: Jacobi; fewer where the grid or its split cannot be halved; docs/fluid.md)");
  if (!optionsHelpMode() && (s.viscousMgLevels < 1 || s.viscousMgLevels > 8))
    failOption("-velocity_mg_levels", "must be in [1, 8], got " + std::to_string(s.viscousMgLevels));
  if (!optionsHelpMode() && s.viscousMgLevels > 1 && s.viscousOperator != ViscousOperator::Fused)
    failOption("-velocity_mg_levels", "the multigrid preconditions the fused CG only (-velocity_operator fused)");
  o.real("-velocity_ksp_rtol", 1e-6, "Viscous relative tolerance (measured choice, docs/fluid.md)");
  return s;
}

void SolverOptions::validate(int ranks, int zCells, bool weightedProjection) const
{
  if (pressurePc == "fft" && ranks > zCells)
    failOption("-pressure_pc_type", "fft splits the z axis into slabs, one z cell per rank at least: " + std::to_string(ranks) +
                                        " ranks for " + std::to_string(zCells) + " z cells; use at most " + std::to_string(zCells) +
                                        " ranks or -pressure_pc_type hypre, pfmg or mg");
  if (weightedProjection && directPressure())
    failOption("-penalization_projection", "weighted needs an iterative pressure solve: the direct fft solve is exact for the "
                                           "constant-coefficient equation only (use -pressure_pc_type hypre, pfmg or mg)");
}

} // namespace vp
