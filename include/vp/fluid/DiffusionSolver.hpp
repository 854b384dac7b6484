#pragma once
// The implicit (Crank-Nicolson) viscous step for a velocity increment du with homogeneous
// boundary conditions: (I + theta - a L) du = r, a = nu dt / 2, L the face Laplacian with the ghost
// rules of Boundary.hpp, theta >= 0 the implicit penalization chi lambda dt. The quadratic wall
// extrapolation makes L non-symmetric, but S L is symmetric for the diagonal weights
// S = (3/4)^(number of no-slip walls the face is next to), so the solver works on
// (S (1 + theta) - a S L) du = S r, symmetric positive definite (KSP prefix -velocity_).
// The operator is matrix-free by default (-velocity_operator shell: one fused stencil sweep per
// product, CG + Jacobi); -velocity_operator assembled builds the AIJ matrix for preconditioners
// that need one (hypre, gamg), useful when nu dt / h^2 is large (docs/fluid.md, solver table).
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

  // Solves (I + theta - a L) du = r for du (du holds the initial guess); theta may be null. atol: absolute
  // tolerance on the S-weighted residual unless -velocity_ksp_atol is given. Returns iterations.
  int solve(double a, Vec r, Vec du, double atol, Vec theta = nullptr);

  // The operator S (1 + theta) - a S L of the last solve (or of setOperator), shell or assembled.
  Mat operatorMatrix() const { return assembled_ ? A_ : shell_; }
  void setOperator(double a, Vec theta);
  Vec weights() const { return S_; }  // S
  bool assembled() const { return assembled_; }

  // One face's row of S L: weight S, diagonal and the coefficients to the -1 / +1 neighbours.
  struct Row {
    bool fixed = false;  // a wall-normal face: identity row, the increment stays zero
    double weight = 1, diag = 0, off[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  };
  Row row(int c, const PetscInt p[3]) const;

private:
  void assemble();
  static PetscErrorCode mult(Mat A, Vec x, Vec y);
  static PetscErrorCode diagonal(Mat A, Vec d);

  const Grid& grid_;
  const BoundaryConfig bc_;
  bool assembled_ = false;
  Mat SL_ = nullptr, A_ = nullptr, shell_ = nullptr;
  Vec S_ = nullptr, SdiagL_ = nullptr, rhs_ = nullptr, diag_ = nullptr, xL_ = nullptr;
  Vec theta_ = nullptr;
  KSP ksp_ = nullptr;
  double a_ = -1;
  bool userAtol_ = false;
};

} // namespace vp
