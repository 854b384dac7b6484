#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/OptionDefaults.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <string>

namespace vp {

DiffusionSolver::DiffusionSolver(const Grid& grid, const BoundaryConfig& bc) : grid_(grid), bc_(bc)
{
  assembled_ = readSolverOptions().assembledViscous;
  setOptionDefault("-velocity_ksp_type", "cg");
  setOptionDefault("-velocity_pc_type", "jacobi");
  setOptionDefault("-velocity_ksp_norm_type", "unpreconditioned");
  // Measured (docs/fluid.md, tolerances): results change by < 1e-7 relative to rtol 1e-10.
  setOptionDefault("-velocity_ksp_rtol", "1e-6");
  PetscBool set;
  VP_CALL(PetscOptionsHasName(nullptr, "velocity_", "-ksp_atol", &set));
  userAtol_ = set;
  DM f = grid.faceSolveDM();
  for (Vec* v : {&S_, &SdiagL_, &rhs_, &diag_}) VP_CALL(DMCreateGlobalVector(f, v));
  VP_CALL(DMCreateLocalVector(f, &xL_));
  {
    PetscScalar ****s, ****dl;
    VP_CALL(DMDAVecGetArrayDOF(f, S_, &s));
    VP_CALL(DMDAVecGetArrayDOF(f, SdiagL_, &dl));
    for (PetscInt k = grid.start(2); k < grid.end(2); ++k)
      for (PetscInt j = grid.start(1); j < grid.end(1); ++j)
        for (PetscInt i = grid.start(0); i < grid.end(0); ++i)
          for (int c = 0; c < 3; ++c) {
            const PetscInt p[3] = {i, j, k};
            const Row r = row(c, p);
            s[k][j][i][c] = r.weight;
            dl[k][j][i][c] = r.weight * r.diag;
          }
    VP_CALL(DMDAVecRestoreArrayDOF(f, SdiagL_, &dl));
    VP_CALL(DMDAVecRestoreArrayDOF(f, S_, &s));
  }
  if (assembled_) {
    assemble();
    VP_CALL(MatDuplicate(SL_, MAT_DO_NOT_COPY_VALUES, &A_));
  } else {
    PetscInt n;
    VP_CALL(VecGetLocalSize(S_, &n));
    VP_CALL(MatCreateShell(grid.comm(), n, n, PETSC_DETERMINE, PETSC_DETERMINE, this, &shell_));
    VP_CALL(MatShellSetOperation(shell_, MATOP_MULT, (void (*)(void))mult));
    VP_CALL(MatShellSetOperation(shell_, MATOP_GET_DIAGONAL, (void (*)(void))diagonal));
    VP_CALL(MatSetOption(shell_, MAT_SYMMETRIC, PETSC_TRUE));
    VP_CALL(MatSetDM(shell_, f));
  }
  VP_CALL(KSPCreate(grid.comm(), &ksp_));
  VP_CALL(KSPSetOptionsPrefix(ksp_, "velocity_"));
  VP_CALL(KSPSetFromOptions(ksp_));
  VP_CALL(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE));
}

DiffusionSolver::~DiffusionSolver()
{
  KSPDestroy(&ksp_);
  for (Vec* v : {&S_, &SdiagL_, &rhs_, &diag_, &xL_}) VecDestroy(v);
  MatDestroy(&shell_);
  MatDestroy(&A_);
  MatDestroy(&SL_);
}

DiffusionSolver::Row DiffusionSolver::row(int c, const PetscInt p[3]) const
{
  const Grid& g = grid_;
  Row r;
  if (isFixedFace(g, c, p[c])) {
    r.fixed = true;
    return r;
  }
  for (int d = 0; d < 3; ++d) {
    const double w = 1 / (g.h(d) * g.h(d));
    if (g.n(d) == 1 && g.periodic(d)) continue;  // one periodic cell: the neighbours are itself
    r.diag -= 2 * w;
    for (int side = 0; side < 2; ++side) {
      const PetscInt q = p[d] + (side ? 1 : -1);
      const bool outside = !g.periodic(d) && (q < 0 || q >= g.n(d));
      if (d == c) {
        // Normal direction: the wall faces 0 and N are fixed (zero for an increment).
        if (!g.periodic(d) && (q <= 0 || q >= g.n(d))) continue;
        r.off[d][side] += w;
      } else if (!outside) {
        r.off[d][side] += w;
      } else if (bc_.type[2 * d + side] == BcType::Slip) {
        r.diag += w;  // u_g = u_0
      } else {
        // u_g = (-6 u_0 + u_1)/3 for an increment (wall value zero)
        r.diag -= 2 * w;
        r.off[d][1 - side] += w / 3;
        r.weight *= 0.75;
      }
    }
  }
  return r;
}

void DiffusionSolver::assemble()
{
  const Grid& g = grid_;
  VP_CALL(DMCreateMatrix(g.faceSolveDM(), &SL_));
  VP_CALL(MatSeqAIJSetPreallocation(SL_, 7, nullptr));
  VP_CALL(MatMPIAIJSetPreallocation(SL_, 7, nullptr, 3, nullptr));
  VP_CALL(MatSetOption(SL_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        for (int c = 0; c < 3; ++c) {
          const PetscInt p[3] = {i, j, k};
          const Row r = row(c, p);
          MatStencil me = {k, j, i, c}, col[7];
          PetscScalar v[7];
          int n = 0;
          for (int d = 0; d < 3; ++d)
            for (int side = 0; side < 2; ++side) {
              if (r.off[d][side] == 0) continue;
              PetscInt q[3] = {i, j, k};
              q[d] += side ? 1 : -1;
              col[n] = {q[2], q[1], q[0], c};
              v[n++] = r.weight * r.off[d][side];
            }
          col[n] = me;
          v[n++] = r.weight * r.diag;  // zero for a fixed face: a decoupled row of S (1 + theta) - a S L
          VP_CALL(MatSetValuesStencil(SL_, 1, &me, n, col, v, ADD_VALUES));
        }
  VP_CALL(MatAssemblyBegin(SL_, MAT_FINAL_ASSEMBLY));
  VP_CALL(MatAssemblyEnd(SL_, MAT_FINAL_ASSEMBLY));
}

// y = S (1 + theta) x - a S L x in one sweep over the ghosted x. Every face component has the same
// 7-point form once the wall ghosts hold the homogeneous boundary rules (Boundary.hpp), so a grid
// row of 3 xm values is one contiguous, vectorisable loop; fixed wall faces are identity rows.
PetscErrorCode DiffusionSolver::mult(Mat A, Vec x, Vec y)
{
  DiffusionSolver* self;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &self));
  const Grid& g = self->grid_;
  DM f = g.faceSolveDM();
  PetscCall(DMGlobalToLocal(f, x, INSERT_VALUES, self->xL_));
  {
    FaceArray xa(f, self->xL_);
    fillFaceGhosts(g, self->bc_, xa.a, true);
  }
  PetscInt gs[3], gm[3];
  PetscCall(DMDAGetGhostCorners(f, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscScalar *xl, *xg, *s, *th = nullptr;
  PetscScalar* ya;
  PetscCall(VecGetArrayRead(self->xL_, &xl));
  PetscCall(VecGetArrayRead(x, &xg));  // the ghost fill zeroes the fixed faces in xL
  PetscCall(VecGetArrayRead(self->S_, &s));
  if (self->theta_) PetscCall(VecGetArrayRead(self->theta_, &th));
  PetscCall(VecGetArray(y, &ya));
  const double a = self->a_;
  const double wx = a / (g.h(0) * g.h(0)), wy = a / (g.h(1) * g.h(1)), wz = a / (g.h(2) * g.h(2));
  const double wc = 1 + 2 * (wx + wy + wz);
  const PetscInt sx = 3, sy = 3 * gm[0], sz = 3 * gm[0] * gm[1];
  const PetscInt row = 3 * (g.end(0) - g.start(0));
  PetscInt o = 0;  // owned (global-vector) offset of the row
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j, o += row) {
      // __restrict: y never aliases x, S or theta, so the compiler may vectorise the row.
      const PetscScalar* __restrict xr = xl + (k - gs[2]) * sz + (j - gs[1]) * sy + (g.start(0) - gs[0]) * sx;
      const PetscScalar* __restrict sr = s + o;
      PetscScalar* __restrict yr = ya + o;
      if (th) {
        const PetscScalar* __restrict tr = th + o;
        for (PetscInt n = 0; n < row; ++n)
          yr[n] = sr[n] * ((wc + tr[n]) * xr[n] - wx * (xr[n + sx] + xr[n - sx]) - wy * (xr[n + sy] + xr[n - sy]) -
                           wz * (xr[n + sz] + xr[n - sz]));
      } else {
        for (PetscInt n = 0; n < row; ++n)
          yr[n] = sr[n] * (wc * xr[n] - wx * (xr[n + sx] + xr[n - sx]) - wy * (xr[n + sy] + xr[n - sy]) -
                           wz * (xr[n + sz] + xr[n - sz]));
      }
      // Decoupled rows (1 + theta) x of the fixed wall faces (their increment is zero).
      const PetscScalar* tr = th ? th + o : nullptr;
      auto fixedRow = [&](PetscInt n) { yr[n] = (tr ? 1 + tr[n] : 1) * xg[o + n]; };
      if (g.atLow(0)) fixedRow(0);
      if (j == 0 && g.atLow(1))
        for (PetscInt n = 1; n < row; n += 3) fixedRow(n);
      if (k == 0 && g.atLow(2))
        for (PetscInt n = 2; n < row; n += 3) fixedRow(n);
    }
  PetscCall(VecRestoreArray(y, &ya));
  if (th) PetscCall(VecRestoreArrayRead(self->theta_, &th));
  PetscCall(VecRestoreArrayRead(self->S_, &s));
  PetscCall(VecRestoreArrayRead(x, &xg));
  PetscCall(VecRestoreArrayRead(self->xL_, &xl));
  PetscFunctionReturn(0);
}

// diag = S (1 + theta) - a S diag(L); 1 + theta on fixed faces (S = 1, diag(L) = 0 there).
PetscErrorCode DiffusionSolver::diagonal(Mat A, Vec d)
{
  DiffusionSolver* self;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &self));
  PetscCall(VecCopy(self->S_, d));
  if (self->theta_) PetscCall(VecPointwiseMult(self->diag_, self->S_, self->theta_));
  if (self->theta_) PetscCall(VecAXPY(d, 1.0, self->diag_));
  PetscCall(VecAXPY(d, -self->a_, self->SdiagL_));
  PetscFunctionReturn(0);
}

void DiffusionSolver::setOperator(double a, Vec theta)
{
  a_ = a;
  theta_ = theta;
  if (assembled_) {
    // A = S (1 + theta) - a S L; the pattern is that of S L, so the preconditioner is rebuilt in place.
    VP_CALL(MatCopy(SL_, A_, SAME_NONZERO_PATTERN));
    VP_CALL(MatScale(A_, -a));
    VP_CALL(VecCopy(S_, diag_));
    if (theta) {
      VP_CALL(VecPointwiseMult(rhs_, S_, theta));
      VP_CALL(VecAXPY(diag_, 1.0, rhs_));
    }
    VP_CALL(MatDiagonalSet(A_, diag_, ADD_VALUES));
  } else {
    // A new state, so that the preconditioner rebuilds its diagonal.
    VP_CALL(MatAssemblyBegin(shell_, MAT_FINAL_ASSEMBLY));
    VP_CALL(MatAssemblyEnd(shell_, MAT_FINAL_ASSEMBLY));
  }
  VP_CALL(KSPSetOperators(ksp_, operatorMatrix(), operatorMatrix()));
}

int DiffusionSolver::solve(double a, Vec r, Vec du, double atol, Vec theta)
{
  // A theta changes every step (moving particles); without it A changes with dt only.
  if (a != a_ || theta || theta_) setOperator(a, theta);
  VP_CALL(VecPointwiseMult(rhs_, S_, r));
  if (!userAtol_) VP_CALL(KSPSetTolerances(ksp_, PETSC_DEFAULT, atol, PETSC_DEFAULT, PETSC_DEFAULT));
  VP_CALL(KSPSolve(ksp_, rhs_, du));
  KSPConvergedReason reason;
  VP_CALL(KSPGetConvergedReason(ksp_, &reason));
  if (reason < 0)
    throw StepFailure(std::string("velocity (diffusion) solve did not converge: ") +
                             KSPConvergedReasons[reason] + " (see -velocity_ksp_monitor)");
  PetscInt its;
  VP_CALL(KSPGetIterationNumber(ksp_, &its));
  return static_cast<int>(its);
}

} // namespace vp
