#pragma once
// The solver options vpsolve interprets itself (listed by -help, written to run.json), read once
// with the run's configuration and handed to the solvers; every other -pressure_* / -velocity_*
// option goes to PETSc's KSP and PC objects unchanged (docs/fluid.md).
#include <string>

namespace vp {

enum class ViscousOperator { Fused, Shell, Assembled };

struct SolverOptions {
  std::string pressurePc;        // -pressure_pc_type: hypre (BoomerAMG), fft, pfmg, mg or another PETSc PC
  std::string pressureKsp;       // -pressure_ksp_type ("" : cg, or preonly with fft)
  int pressureGuesses = 5;       // -pressure_guesses: earlier solutions that form an iterative solve's start
  ViscousOperator viscousOperator = ViscousOperator::Fused;  // -velocity_operator
  int viscousMgLevels = 1;       // -velocity_mg_levels: grids of the fused CG's multigrid (1: Jacobi)

  // One application of the preconditioner is the solve (fft, unless a Krylov method is given).
  bool directPressure() const { return !pressureKsp.empty() ? pressureKsp == "preonly" : pressurePc == "fft"; }
  // What the choices need of the run: the fft's slabs one z cell per rank at least, an iterative
  // solve for the weighted projection (throws InputError).
  void validate(int ranks, int zCells, bool weightedProjection) const;
};

SolverOptions readSolverOptions();

} // namespace vp
