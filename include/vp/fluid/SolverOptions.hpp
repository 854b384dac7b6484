#pragma once
// The solver options vpsolve interprets itself (listed by -help, written to run.json); every other
// -pressure_* / -velocity_* option goes to PETSc's KSP and PC objects unchanged (docs/fluid.md).
#include <string>

namespace vp {

enum class ViscousOperator { Fused, Shell, Assembled };

struct SolverOptions {
  std::string pressurePc;        // -pressure_pc_type: hypre (BoomerAMG), fft, pfmg, mg or another PETSc PC
  std::string pressureKsp;       // -pressure_ksp_type ("" : cg, or preonly with fft)
  int pressureGuesses = 5;       // -pressure_guesses: earlier solutions that form an iterative solve's start
  ViscousOperator viscousOperator = ViscousOperator::Fused;  // -velocity_operator
};

SolverOptions readSolverOptions();

} // namespace vp
