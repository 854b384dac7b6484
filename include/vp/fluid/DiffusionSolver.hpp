#pragma once
// The implicit (Crank-Nicolson) viscous step for a velocity increment du with homogeneous
// boundary conditions: (I + theta - a L) du = r, a = nu dt / 2, L the face Laplacian with the ghost
// rules of Boundary.hpp, theta >= 0 the implicit penalization chi lambda dt. The quadratic wall
// extrapolation makes L non-symmetric, but S L is symmetric for the diagonal weights
// S = (3/4)^(number of no-slip walls the face is next to), so the solver works on
// (S (1 + theta) - a S L) du = S r, symmetric positive definite (KSP prefix -velocity_).
// The operator is matrix-free by default (one stencil sweep per product) and solved by a
// hand-fused CG + Jacobi (-velocity_operator fused: the product carries the dot product p.Ap, one
// pass updates x and r and forms both residual dot products, one pass the search direction; PETSc's
// CG makes seven vector passes per iteration). -velocity_operator shell gives the same operator to
// PETSc's KSP (other Krylov methods, monitors); -velocity_operator assembled builds the AIJ matrix
// for preconditioners that need one (hypre, gamg), useful when nu dt / h^2 is large (docs/fluid.md).
#include "vp/core/Config.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/grid/GhostRefresh.hpp"
#include "vp/grid/Grid.hpp"
#include <petscksp.h>

namespace vp {

class DiffusionSolver {
public:
  DiffusionSolver(const Grid& grid, const BoundaryConfig& bc, ViscousOperator op);
  ~DiffusionSolver();
  DiffusionSolver(const DiffusionSolver&) = delete;
  DiffusionSolver& operator=(const DiffusionSolver&) = delete;

  // Solves (I + theta - a L) du = r for du (du holds the initial guess; r is overwritten by S r);
  // theta may be null. atol: absolute tolerance on the S-weighted residual unless
  // -velocity_ksp_atol is given. Returns iterations.
  int solve(double a, Vec r, Vec du, double atol, Vec theta = nullptr);

  // The operator S (1 + theta) - a S L of the last solve (or of setOperator), shell or assembled.
  Mat operatorMatrix() const { return assembled_ ? A_ : shell_; }
  void setOperator(double a, Vec theta);
  Vec weights() const { return S_; }  // S
  bool assembled() const { return assembled_; }
  bool fused() const { return fused_; }

  // y = A x. x global, or local (its owned values set, zero on the fixed wall faces; the ghosts
  // are updated here) when `local` is set, as in the fused CG; then `dot` also returns this rank's
  // part of x.y.
  double apply(Vec x, Vec y, bool dot, bool local = false);

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
  // f(global offset, local offset, length) for every owned grid row of 3 nx values.
  template <class F>
  void forRows(F f) const;
  // f(global offset) for every owned fixed wall face (face 0 of a wall-bounded axis).
  template <class F>
  void forFixedFaces(F f) const;
  // CG + Jacobi on A du = b with PETSc's default convergence test on the unpreconditioned residual.
  int fusedSolve(Vec b, Vec du, double atol);

  const Grid& grid_;
  const BoundaryConfig bc_;
  const GhostRefresh ghosts_;  // of a local direction (fused CG)
  bool assembled_ = false, fused_ = false;
  Mat SL_ = nullptr, A_ = nullptr, shell_ = nullptr;
  Vec S_ = nullptr, SdiagL_ = nullptr, diag_ = nullptr, xL_ = nullptr;  // diag_: assembled only
  Vec theta_ = nullptr;
  Vec r_ = nullptr, q_ = nullptr, dinv_ = nullptr;  // fused CG: residual, A p, 1/diag (the direction: xL_)
  KSP ksp_ = nullptr;
  double a_ = -1;
  bool userAtol_ = false;
};

} // namespace vp
