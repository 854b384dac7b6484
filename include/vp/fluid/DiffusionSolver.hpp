#pragma once
// The implicit (Crank-Nicolson) viscous step for a velocity increment du with homogeneous
// boundary conditions: (I + theta - a L) du = r, a = nu dt / 2, L the face Laplacian with the ghost
// rules of Boundary.hpp, theta >= 0 the implicit penalization chi lambda dt. The quadratic wall
// extrapolation makes L non-symmetric, but S L is symmetric for the diagonal weights
// S = (3/4)^(number of no-slip walls the face is next to), so the solver works on
// (S (1 + theta) - a S L) du = S r, symmetric positive definite (KSP prefix -velocity_).
// The operator is matrix-free by default (one stencil sweep per product) and solved by a
// hand-fused CG + Jacobi (-velocity_operator fused: the product carries the dot product p.Ap, one
// pass updates r and forms both residual dot products, one pass updates x and the search direction;
// PETSc's CG makes seven vector passes per iteration). -velocity_operator shell gives the same operator to
// PETSc's KSP (other Krylov methods, monitors); -velocity_operator assembled builds the AIJ matrix
// for preconditioners that need one (hypre, gamg). With -velocity_mg_levels > 1 the fused CG is
// preconditioned by a geometric multigrid V-cycle (ViscousMultigrid.hpp) instead of Jacobi: its
// iterations stay few as nu dt / h^2 grows (docs/fluid.md).
#include "vp/core/Config.hpp"
#include "vp/core/Error.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/grid/GhostRefresh.hpp"
#include "vp/grid/Grid.hpp"
#include <memory>
#include <utility>
#include <vector>
#include <petscksp.h>

namespace vp {

class ViscousMultigrid;

class DiffusionSolver {
public:
  // mgLevels: the fused CG's preconditioner, 1 Jacobi, more a multigrid V-cycle of at most that many grids.
  DiffusionSolver(const Grid& grid, const BoundaryConfig& bc, ViscousOperator op, int mgLevels = 1);
  ~DiffusionSolver();
  DiffusionSolver(const DiffusionSolver&) = delete;
  DiffusionSolver& operator=(const DiffusionSolver&) = delete;

  // Solves (I + theta - a L) du = r for du (du holds the initial guess; r is overwritten by S r);
  // theta may be null. atol: absolute tolerance on the S-weighted residual unless
  // -velocity_ksp_atol is given. Returns iterations.
  int solve(double a, Vec r, Vec du, double atol, Vec theta = nullptr);

  // The operator S (1 + theta) - a S L of the last solve (or of setOperator), shell or assembled.
  Mat operatorMatrix() const { return assembled_ ? A_ : shell_; }
  // Sets a and theta; theta is read here (its rows' non-zero stretches), so a theta changed in place
  // must be set again (solve() does so).
  void setOperator(double a, Vec theta);
  Vec weights() const { return S_; }  // S
  bool assembled() const { return assembled_; }
  bool fused() const { return fused_; }

  // y = A x. x global, or local (its owned values set, zero on the fixed wall faces; the ghosts
  // are updated here) when `local` is set, as in the fused CG; then `dot` also returns this rank's
  // part of x.y.
  double apply(Vec x, Vec y, bool dot, bool local = false);
  // One sweep of A over a local x (owned values set; ghosts refreshed here) with b global: out =
  // b - A x (omega 0), or the damped Jacobi step out = x + omega D^-1 (b - A x); out local, not x.
  // The fixed wall faces of out are left to the next ghost refresh (it zeroes them). Returns b.out
  // for a Jacobi step, 0 for the residual.
  double sweep(Vec x, Vec b, double omega, Vec out) const;
  // The ghosts of a local vector from its owned values: neighbours' values, homogeneous wall rules.
  void refreshGhosts(Vec local) const;
  // 1 / diag of the operator last set (fused operator).
  Vec inverseDiagonal() const { return dinv_; }
  // The grids of the fused CG's multigrid preconditioner (1: Jacobi).
  int multigridLevels() const;
  const ViscousMultigrid* multigrid() const { return mg_.get(); }
  // f(global offset, local offset, length) for every owned grid row of 3 nx values.
  template <class F>
  void forRows(F f) const;
  // f(global offset) for every owned fixed wall face (face 0 of a wall-bounded axis).
  template <class F>
  void forFixedFaces(F f) const;

  // One face's row of S L: weight S, diagonal and the coefficients to the -1 / +1 neighbours.
  struct Row {
    bool fixed = false;  // a wall-normal face: identity row, the increment stays zero
    double weight = 1, diag = 0, off[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  };
  Row row(int c, const PetscInt p[3]) const;

private:
  struct Weights {
    double w[3], centre;  // a / h^2 per axis, 1 + 2 sum of them
    PetscInt stride[3];   // of the ghosted local array
  };
  Weights weights(const PetscInt ghostSize[3]) const;
  static void stencilRange(PetscInt b, PetscInt e, const Weights& w, const PetscScalar* xr, const PetscScalar* sr,
                           const PetscScalar* tr, PetscScalar* yr);
  void stencilRow(PetscInt r, PetscInt len, const Weights& w, const PetscScalar* xr, const PetscScalar* sr,
                  const PetscScalar* tr, PetscScalar* yr) const;
  // Each row's range of values where theta may be non-zero (thetaRows_).
  void markTheta(Vec theta);
  void assemble();
  static PetscErrorCode mult(Mat A, Vec x, Vec y);
  static PetscErrorCode diagonal(Mat A, Vec d);
  // CG + Jacobi (or the multigrid) on A du = b with PETSc's default convergence test on the
  // unpreconditioned residual.
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
  std::unique_ptr<ViscousMultigrid> mg_;
  Vec z_ = nullptr;  // the preconditioned residual in the local layout (multigrid)
  double a_ = -1;
  bool userAtol_ = false;
  std::vector<PetscInt> weighted_;                    // owned offsets of the faces with S != 1
  std::vector<std::pair<PetscInt, PetscInt>> unitS_;  // per owned row: the range of its values where S = 1
  std::vector<std::pair<PetscInt, PetscInt>> thetaRows_;  // per owned row: outside this range theta is 0
};

template <class F>
inline void DiffusionSolver::forRows(F f) const
{
  const Grid& g = grid_;
  PetscInt gs[3], gm[3];
  VP_CALL(DMDAGetGhostCorners(g.faceSolveDM(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscInt row = 3 * (g.end(0) - g.start(0));
  PetscInt o = 0;
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j, o += row)
      f(o, 3 * (((k - gs[2]) * gm[1] + (j - gs[1])) * gm[0] + g.start(0) - gs[0]), row);
}

template <class F>
inline void DiffusionSolver::forFixedFaces(F f) const
{
  const Grid& g = grid_;
  const PetscInt row = 3 * (g.end(0) - g.start(0));
  PetscInt o = 0;
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j, o += row) {
      if (g.atLow(0)) f(o);
      if (j == 0 && g.atLow(1))
        for (PetscInt n = 1; n < row; n += 3) f(o + n);
      if (k == 0 && g.atLow(2))
        for (PetscInt n = 2; n < row; n += 3) f(o + n);
    }
}

} // namespace vp
