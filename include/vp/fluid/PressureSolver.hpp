#pragma once
// The pressure Poisson problem -lap_h psi = b, solved as A psi = V b with A = -V lap_h (V the cell
// volume: the finite-volume form, which multigrid coarsens well), lap_h the cell-centred 7-point operator with
// zero normal gradient at walls (symmetric positive semi-definite; the constant null space is
// attached). KSP prefix -pressure_. Defaults: CG + hypre BoomerAMG tuned for the 3-D 7-point
// Laplacian (see docs/fluid.md, linear solvers); -pressure_pc_type mg (geometric multigrid on the DMDA with
// rediscretised coarse levels), -pressure_pc_type pfmg (hypre PFMG) and -pressure_pc_type fft (an
// exact FFT inverse, FftPoisson.hpp; KSP preonly by default with it) also work. The operator
// is assembled and the preconditioner set up once; an iterative solve starts from the fit of the
// last -pressure_guesses solutions to its right-hand side (docs/fluid.md, initial guess).
#include "vp/fluid/SolutionHistory.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/grid/Grid.hpp"
#include <memory>
#include <petscksp.h>

namespace vp {

class PressureSolver {
public:
  // weighted: the operator will come from setFaceWeights (an iterative solver is required).
  PressureSolver(const Grid& grid, const SolverOptions& options, bool weighted = false);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  // Solves -lap_h x = b; b is overwritten (scaled by V, made consistent by removing its mean); x
  // holds the initial guess. atol: absolute tolerance on -lap_h x - b unless -pressure_ksp_atol is
  // given (then it applies to the scaled system). Returns iterations.
  int solve(Vec b, Vec x, double atol);
  // The solutions the next starts are fitted from (null for a direct solve or -pressure_guesses 0).
  SolutionHistory* history() const { return history_.get(); }
  Mat matrix() const;  // A = -V lap_h
  // From now on A = -V div(beta grad) with beta a face field (faceDM local vector, ghosts valid):
  // the weighted projection of the penalized step (Projection.hpp). Assembles A every call (the
  // mask moves), and the preconditioner is set up again for it.
  void setFaceWeights(Vec betaLocal);
  KSP ksp() const { return ksp_; }

  struct Box {
    double lo[3], hi[3];  // domain box: the operator of every multigrid level is built from it
  };

private:
  const Grid& grid_;
  KSP ksp_ = nullptr;
  MatNullSpace nullSpace_ = nullptr;
  Vec work_ = nullptr;
  bool userAtol_ = false;
  std::unique_ptr<SolutionHistory> history_;
  bool direct_ = false;  // -pressure_ksp_type preonly (e.g. with the exact fft PC): no initial guess
  Box box_;
  Mat weightedA_ = nullptr;  // setFaceWeights
};

} // namespace vp
