#pragma once
// The implicit (Crank-Nicolson) viscous step for a velocity increment du with homogeneous
// boundary conditions: (I - a L) du = r, a = nu dt / 2, L the face Laplacian with the ghost rules
// of Boundary.hpp. The quadratic wall extrapolation makes L non-symmetric, but S L is symmetric
// for the diagonal weights S = (3/4)^(number of no-slip walls the face is next to), so the solver
// works on (S - a S L) du = S r, symmetric positive definite: CG + Jacobi by default
// (KSP prefix -velocity_).
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"
#include <petscksp.h>

namespace vp {

class DiffusionSolver {
public:
  DiffusionSolver(const Grid& grid, const BoundaryConfig& bc);
  ~DiffusionSolver();
  DiffusionSolver(const DiffusionSolver&) = delete;
  DiffusionSolver& operator=(const DiffusionSolver&) = delete;

  // Solves (I + theta - a L) du = r for du (initial guess zero); theta (>= 0 per face, e.g. the
  // implicit penalization chi lambda dt) may be null. Returns iterations.
  int solve(double a, Vec r, Vec du, double atol, Vec theta = nullptr);

  Mat scaledLaplacian() const { return SL_; }  // S L
  Vec weights() const { return S_; }           // S

private:
  void assemble(const BoundaryConfig& bc);

  const Grid& grid_;
  Mat SL_ = nullptr, A_ = nullptr;
  Vec S_ = nullptr, rhs_ = nullptr, diag_ = nullptr;
  KSP ksp_ = nullptr;
  double a_ = -1;
  bool userAtol_ = false;
};

} // namespace vp
