#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/OptionDefaults.hpp"
#include "vp/grid/Boundary.hpp"
#include <string>

namespace vp {

DiffusionSolver::DiffusionSolver(const Grid& grid, const BoundaryConfig& bc) : grid_(grid)
{
  setOptionDefault("-velocity_ksp_type", "cg");
  setOptionDefault("-velocity_pc_type", "jacobi");
  setOptionDefault("-velocity_ksp_norm_type", "unpreconditioned");
  setOptionDefault("-velocity_ksp_rtol", "1e-10");
  PetscBool set;
  VP_CALL(PetscOptionsHasName(nullptr, "velocity_", "-ksp_atol", &set));
  userAtol_ = set;
  assemble(bc);
  VP_CALL(MatDuplicate(SL_, MAT_DO_NOT_COPY_VALUES, &A_));
  VP_CALL(DMCreateGlobalVector(grid.faceSolveDM(), &rhs_));
  VP_CALL(DMCreateGlobalVector(grid.faceSolveDM(), &diag_));
  VP_CALL(KSPCreate(grid.comm(), &ksp_));
  VP_CALL(KSPSetOptionsPrefix(ksp_, "velocity_"));
  VP_CALL(KSPSetFromOptions(ksp_));
}

DiffusionSolver::~DiffusionSolver()
{
  KSPDestroy(&ksp_);
  VecDestroy(&diag_);
  VecDestroy(&rhs_);
  VecDestroy(&S_);
  MatDestroy(&A_);
  MatDestroy(&SL_);
}

void DiffusionSolver::assemble(const BoundaryConfig& bc)
{
  const Grid& g = grid_;
  VP_CALL(DMCreateMatrix(g.faceSolveDM(), &SL_));
  VP_CALL(MatSeqAIJSetPreallocation(SL_, 7, nullptr));
  VP_CALL(MatMPIAIJSetPreallocation(SL_, 7, nullptr, 3, nullptr));
  VP_CALL(MatSetOption(SL_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  VP_CALL(DMCreateGlobalVector(g.faceSolveDM(), &S_));
  PetscScalar**** s;
  VP_CALL(DMDAVecGetArrayDOF(g.faceSolveDM(), S_, &s));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        for (int c = 0; c < 3; ++c) {
          const PetscInt p[3] = {i, j, k};
          MatStencil row = {k, j, i, c}, col[7];
          PetscScalar v[7];
          int n = 0;
          if (isFixedFace(g, c, p[c])) {
            s[k][j][i][c] = 1;
            col[n] = row;
            v[n++] = 0;  // identity row of S - a S L
            VP_CALL(MatSetValuesStencil(SL_, 1, &row, n, col, v, ADD_VALUES));
            continue;
          }
          double weight = 1, diag = 0;
          double off[3][2] = {{0, 0}, {0, 0}, {0, 0}};  // coefficient to the -1 / +1 neighbour
          for (int d = 0; d < 3; ++d) {
            const double w = 1 / (g.h(d) * g.h(d));
            diag -= 2 * w;
            if (g.n(d) == 1 && g.periodic(d)) {  // one periodic cell: the neighbours are itself
              diag += 2 * w;
              continue;
            }
            for (int side = 0; side < 2; ++side) {
              const PetscInt q = p[d] + (side ? 1 : -1);
              const bool outside = !g.periodic(d) && (q < 0 || q >= g.n(d));
              if (d == c) {
                // Normal direction: the wall faces 0 and N are fixed (zero for an increment).
                if (!g.periodic(d) && (q <= 0 || q >= g.n(d))) continue;
                off[d][side] += w;
              } else if (!outside) {
                off[d][side] += w;
              } else if (bc.type[2 * d + side] == BcType::Slip) {
                diag += w;  // u_g = u_0
              } else {
                // u_g = (-6 u_0 + u_1)/3 for an increment (wall value zero)
                diag -= 2 * w;
                off[d][1 - side] += w / 3;
                weight *= 0.75;
              }
            }
          }
          s[k][j][i][c] = weight;
          for (int d = 0; d < 3; ++d)
            for (int side = 0; side < 2; ++side) {
              if (off[d][side] == 0) continue;
              PetscInt q[3] = {i, j, k};
              q[d] += side ? 1 : -1;
              col[n] = {q[2], q[1], q[0], c};
              v[n++] = weight * off[d][side];
            }
          col[n] = row;
          v[n++] = weight * diag;
          VP_CALL(MatSetValuesStencil(SL_, 1, &row, n, col, v, ADD_VALUES));
        }
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceSolveDM(), S_, &s));
  VP_CALL(MatAssemblyBegin(SL_, MAT_FINAL_ASSEMBLY));
  VP_CALL(MatAssemblyEnd(SL_, MAT_FINAL_ASSEMBLY));
}

int DiffusionSolver::solve(double a, Vec r, Vec du, double atol, Vec theta)
{
  if (a != a_ || theta) {
    // A = S (1 + theta) - a S L; the pattern is that of S L, so the preconditioner is rebuilt in
    // place. A theta changes every step (moving particles); without it A changes with dt only.
    VP_CALL(MatCopy(SL_, A_, SAME_NONZERO_PATTERN));
    VP_CALL(MatScale(A_, -a));
    VP_CALL(VecCopy(S_, diag_));
    if (theta) {
      VP_CALL(VecPointwiseMult(rhs_, S_, theta));
      VP_CALL(VecAXPY(diag_, 1.0, rhs_));
    }
    VP_CALL(MatDiagonalSet(A_, diag_, ADD_VALUES));
    VP_CALL(KSPSetOperators(ksp_, A_, A_));
    a_ = theta ? -1 : a;
  }
  VP_CALL(VecPointwiseMult(rhs_, S_, r));
  if (!userAtol_) VP_CALL(KSPSetTolerances(ksp_, PETSC_DEFAULT, atol, PETSC_DEFAULT, PETSC_DEFAULT));
  VP_CALL(VecSet(du, 0));
  VP_CALL(KSPSolve(ksp_, rhs_, du));
  KSPConvergedReason reason;
  VP_CALL(KSPGetConvergedReason(ksp_, &reason));
  if (reason < 0)
    throw std::runtime_error(std::string("velocity (diffusion) solve did not converge: ") +
                             KSPConvergedReasons[reason] + " (see -velocity_ksp_monitor)");
  PetscInt its;
  VP_CALL(KSPGetIterationNumber(ksp_, &its));
  return static_cast<int>(its);
}

} // namespace vp
