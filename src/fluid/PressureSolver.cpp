#include "vp/fluid/PressureSolver.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/OptionDefaults.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/fluid/FftPoisson.hpp"
#include "vp/grid/FieldArray.hpp"
#include <algorithm>
#include <string>

namespace vp {

namespace {

// Sets the rows of the cells [xs, xs + xm) of an M-cell grid to the flux balance -V div(c grad):
// w[d] = V / h_d^2, c = coefficient(d, f) on the face f (the index of the cell above it along d).
// Neighbours across a wall do not exist: zero flux (Neumann); a periodic axis one cell thick has no
// gradient.
template <class Coefficient>
PetscErrorCode setFluxBalance(Mat B, const PetscInt M[3], const bool periodic[3], const PetscInt xs[3],
                              const PetscInt xm[3], const double w[3], Coefficient coefficient, InsertMode mode)
{
  PetscFunctionBeginUser;
  for (PetscInt k = xs[2]; k < xs[2] + xm[2]; ++k)
    for (PetscInt j = xs[1]; j < xs[1] + xm[1]; ++j)
      for (PetscInt i = xs[0]; i < xs[0] + xm[0]; ++i) {
        MatStencil row = {k, j, i, 0}, col[7];
        PetscScalar v[7];
        int n = 0;
        double diag = 0;
        for (int d = 0; d < 3; ++d)
          for (int s = -1; s <= 1; s += 2) {
            PetscInt q[3] = {i, j, k};
            q[d] += s;
            if (!periodic[d] && (q[d] < 0 || q[d] >= M[d])) continue;
            if (M[d] == 1) continue;
            PetscInt f[3] = {i, j, k};  // the face between the cell and q
            if (s > 0) f[d] += 1;
            const double c = w[d] * coefficient(d, f);
            col[n] = {q[2], q[1], q[0], 0};
            v[n++] = -c;
            diag += c;
          }
        col[n] = row;
        v[n++] = diag;
        PetscCall(MatSetValuesStencil(B, 1, &row, n, col, v, mode));
      }
  PetscFunctionReturn(0);
}

// Assembles -lap_h on whatever level DM the KSP hands over (PCMG calls it on every coarse level).
PetscErrorCode computeOperator(KSP ksp, Mat A, Mat B, void* ctx)
{
  auto* box = static_cast<PressureSolver::Box*>(ctx);
  DM da;
  PetscInt M[3], xs[3], xm[3];
  DMBoundaryType bt[3];
  PetscFunctionBeginUser;
  PetscCall(KSPGetDM(ksp, &da));
  PetscCall(DMDAGetInfo(da, nullptr, &M[0], &M[1], &M[2], nullptr, nullptr, nullptr, nullptr, nullptr,
                        &bt[0], &bt[1], &bt[2], nullptr));
  PetscCall(DMDAGetCorners(da, &xs[0], &xs[1], &xs[2], &xm[0], &xm[1], &xm[2]));
  // Scaled by the cell volume (a finite-volume flux balance): with piecewise-constant transfers
  // the rediscretised coarse operators are then within a factor 2 of the Galerkin ones.
  double h[3], w[3];
  bool periodic[3];
  for (int d = 0; d < 3; ++d) h[d] = (box->hi[d] - box->lo[d]) / M[d];
  for (int d = 0; d < 3; ++d) w[d] = h[0] * h[1] * h[2] / (h[d] * h[d]);
  for (int d = 0; d < 3; ++d) periodic[d] = bt[d] == DM_BOUNDARY_PERIODIC;
  PetscCall(setFluxBalance(B, M, periodic, xs, xm, w, [](int, const PetscInt*) { return 1.0; }, ADD_VALUES));
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  MatNullSpace ns;
  PetscCall(MatNullSpaceCreate(PetscObjectComm((PetscObject)B), PETSC_TRUE, 0, nullptr, &ns));
  PetscCall(MatSetNullSpace(B, ns));
  if (A != B) PetscCall(MatSetNullSpace(A, ns));
  PetscCall(MatNullSpaceDestroy(&ns));
  PetscFunctionReturn(0);
}

// Number of multigrid levels: halve while every axis stays even, with at least 2 cells and 1 cell
// per rank; coarse[] gets the coarsest grid.
int mgLevels(const Grid& g, PetscInt coarse[3])
{
  PetscInt procs[3];
  VP_CALL(DMDAGetInfo(g.cellDM(), nullptr, nullptr, nullptr, nullptr, &procs[0], &procs[1], &procs[2], nullptr,
                      nullptr, nullptr, nullptr, nullptr, nullptr));
  int levels = 1;
  PetscInt n[3] = {g.n(0), g.n(1), g.n(2)};
  for (;;) {
    bool ok = true;
    for (int d = 0; d < 3; ++d) ok = ok && n[d] % 2 == 0 && n[d] / 2 >= std::max<PetscInt>(2, procs[d]);
    if (!ok) break;
    for (int d = 0; d < 3; ++d) n[d] /= 2;
    ++levels;
  }
  for (int d = 0; d < 3; ++d) coarse[d] = n[d];
  return levels;
}

} // namespace

PressureSolver::PressureSolver(const Grid& grid, const SolverOptions& options, bool weighted) : grid_(grid)
{
  int size;
  MPI_Comm_size(grid.comm(), &size);
  options.validate(size, grid.n(2), weighted);  // again for solvers built in code (tests, benchmarks)
  const std::string& pcType = options.pressurePc;
  PetscBool set;
  registerFftPreconditioner();
  // fft is an exact inverse: one application (preonly) is the solve.
  const bool direct = options.directPressure();
  setOptionDefault("-pressure_ksp_type", direct ? KSPPREONLY : KSPCG);
  if (!direct) {
    setOptionDefault("-pressure_ksp_norm_type", "unpreconditioned");
    // Measured (docs/fluid.md, tolerances): results change by < 1e-7 relative to rtol 1e-10, and
    // max |div u| dx/|u| stays below 1e-6 even after impulsive starts.
    setOptionDefault("-pressure_ksp_rtol", "1e-6");
  }
  if (pcType == "hypre") {
    setOptionDefault("-pressure_pc_type", "hypre");
    setOptionDefault("-pressure_pc_hypre_type", "boomeramg");
    char hypre[64] = "boomeramg";
    VP_CALL(PetscOptionsGetString(nullptr, "pressure_", "-pc_hypre_type", hypre, sizeof hypre, &set));
    if (std::string(hypre) == "boomeramg") {
      // Tuned for the 3-D 7-point Laplacian (benchmarks/RESULTS.md): HMIS coarsening with
      // aggressive coarsening on the first two levels, long-range interpolation, and a Chebyshev
      // smoother (symmetric, so CG stays valid): 2.2x faster per solve than PETSc's defaults.
      setOptionDefault("-pressure_pc_hypre_boomeramg_coarsen_type", "HMIS");
      setOptionDefault("-pressure_pc_hypre_boomeramg_interp_type", "ext+i");
      setOptionDefault("-pressure_pc_hypre_boomeramg_P_max", "4");
      setOptionDefault("-pressure_pc_hypre_boomeramg_strong_threshold", "0.6");
      setOptionDefault("-pressure_pc_hypre_boomeramg_agg_nl", "2");
      setOptionDefault("-pressure_pc_hypre_boomeramg_agg_num_paths", "2");
      // The weighted operator's coefficients jump by the penalization's 1 + lambda dt: there the
      // Chebyshev smoother's eigenvalue estimate fails (an indefinite preconditioner, measured);
      // symmetric Gauss-Seidel (hybrid across ranks) keeps CG valid.
      setOptionDefault("-pressure_pc_hypre_boomeramg_relax_type_all", weighted ? "symmetric-SOR/Jacobi" : "Chebyshev");
    }
  } else if (pcType == "mg") {
    // Q0 transfer with rediscretised coarse operators; Galerkin with Q0 degrades convergence.
    VP_CALL(DMDASetInterpolationType(grid.cellDM(), DMDA_Q0));
    PetscInt coarse[3];
    setOptionDefault("-pressure_pc_mg_levels", std::to_string(mgLevels(grid, coarse)).c_str());
    // The default coarse solve is a dense SVD: beyond a few thousand cells it runs for minutes.
    const PetscInt coarseCells = coarse[0] * coarse[1] * coarse[2], maxCoarseCells = 2000;
    VP_CALL(PetscOptionsHasName(nullptr, "pressure_", "-mg_coarse_pc_type", &set));
    if (!set && coarseCells > maxCoarseCells)
      failOption("-pressure_pc_type", "mg halves the grid while every axis is even: " + std::to_string(grid.n(0)) + " x " +
                                          std::to_string(grid.n(1)) + " x " + std::to_string(grid.n(2)) + " stops at " +
                                          std::to_string(coarse[0]) + " x " + std::to_string(coarse[1]) + " x " +
                                          std::to_string(coarse[2]) + " = " + std::to_string(coarseCells) +
                                          " cells, too many for its dense coarse solve (at most " +
                                          std::to_string(maxCoarseCells) +
                                          "); choose -grid_n with more factors of 2 or -pressure_pc_type hypre or pfmg");
    // One symmetric SOR sweep as smoother: half the iterations of the default Chebyshev/SOR.
    setOptionDefault("-pressure_mg_levels_ksp_type", "richardson");
    setOptionDefault("-pressure_mg_levels_pc_type", "sor");
    setOptionDefault("-pressure_mg_coarse_pc_type", "redundant");
    setOptionDefault("-pressure_mg_coarse_redundant_pc_type", "svd");  // the coarse operator is singular
  } else if (pcType == "pfmg") {
    VP_CALL(DMSetMatType(grid.cellDM(), MATHYPRESTRUCT));
  }
  VP_CALL(PetscOptionsHasName(nullptr, "pressure_", "-ksp_atol", &set));
  userAtol_ = set;

  VP_CALL(DMCreateGlobalVector(grid.cellDM(), &work_));
  VP_CALL(KSPCreate(grid.comm(), &ksp_));
  VP_CALL(KSPSetOptionsPrefix(ksp_, "pressure_"));
  VP_CALL(KSPSetDM(ksp_, grid.cellDM()));
  for (int d = 0; d < 3; ++d) {
    box_.lo[d] = grid.lo(d);
    box_.hi[d] = grid.hi(d);
  }
  if (pcType == "fft" && direct) {
    // A direct fft solve never applies the operator: an empty shell of its size instead of an
    // assembled matrix (0.1 s and 11 % of the memory at 64^3, 1.3 s at 128^3).
    PetscInt local, global;
    VP_CALL(VecGetLocalSize(work_, &local));
    VP_CALL(VecGetSize(work_, &global));
    Mat shell;
    VP_CALL(MatCreateShell(grid.comm(), local, local, global, global, nullptr, &shell));
    VP_CALL(KSPSetOperators(ksp_, shell, shell));
    VP_CALL(KSPSetDMActive(ksp_, PETSC_FALSE));
    VP_CALL(MatDestroy(&shell));
  } else {
    VP_CALL(KSPSetComputeOperators(ksp_, computeOperator, &box_));
  }
  VP_CALL(KSPSetFromOptions(ksp_));
  PetscBool preonly;
  VP_CALL(PetscObjectTypeCompare((PetscObject)ksp_, KSPPREONLY, &preonly));
  direct_ = preonly;
  VP_CALL(KSPSetInitialGuessNonzero(ksp_, direct_ ? PETSC_FALSE : PETSC_TRUE));
  PC pcObj;
  PetscBool fft;
  VP_CALL(KSPGetPC(ksp_, &pcObj));
  VP_CALL(PetscObjectTypeCompare((PetscObject)pcObj, "fft", &fft));
  if (fft) {
    // The weights of A = -V lap_h per axis (computeOperator).
    double w[3];
    for (int d = 0; d < 3; ++d) w[d] = grid.cellVolume() / (grid.h(d) * grid.h(d));
    VP_CALL(PCFftSetWeights(pcObj, w));
  }
  VP_CALL(KSPSetUp(ksp_));
  VP_CALL(MatNullSpaceCreate(grid.comm(), PETSC_TRUE, 0, nullptr, &nullSpace_));
  // The fitted start keeps products with an operator that the weighted projection rebuilds every step.
  if (!direct_ && !weighted && options.pressureGuesses > 0)
    history_ = std::make_unique<SolutionHistory>(matrix(), work_, options.pressureGuesses);
}

void PressureSolver::setFaceWeights(Vec betaLocal)
{
  const Grid& g = grid_;
  if (!weightedA_) {
    VP_CALL(DMCreateMatrix(g.cellDM(), &weightedA_));
    VP_CALL(KSPSetDMActive(ksp_, PETSC_FALSE));
  }
  VP_CALL(MatZeroEntries(weightedA_));
  const PetscInt M[3] = {g.n(0), g.n(1), g.n(2)}, xs[3] = {g.start(0), g.start(1), g.start(2)},
                 xm[3] = {g.end(0) - xs[0], g.end(1) - xs[1], g.end(2) - xs[2]};
  const bool periodic[3] = {g.periodic(0), g.periodic(1), g.periodic(2)};
  double w[3];
  for (int d = 0; d < 3; ++d) w[d] = g.cellVolume() / (g.h(d) * g.h(d));
  {
    FaceArray beta(g.faceDM(), betaLocal, true);
    VP_CALL(setFluxBalance(weightedA_, M, periodic, xs, xm, w,
                           [&](int d, const PetscInt* f) { return beta.a[f[2]][f[1]][f[0]][d]; }, INSERT_VALUES));
  }
  VP_CALL(MatAssemblyBegin(weightedA_, MAT_FINAL_ASSEMBLY));
  VP_CALL(MatAssemblyEnd(weightedA_, MAT_FINAL_ASSEMBLY));
  VP_CALL(MatSetNullSpace(weightedA_, nullSpace_));
  VP_CALL(KSPSetOperators(ksp_, weightedA_, weightedA_));
}

PressureSolver::~PressureSolver()
{
  MatDestroy(&weightedA_);
  VecDestroy(&work_);
  MatNullSpaceDestroy(&nullSpace_);
  KSPDestroy(&ksp_);
}

Mat PressureSolver::matrix() const
{
  Mat A;
  VP_CALL(KSPGetOperators(ksp_, &A, nullptr));
  return A;
}

int PressureSolver::solve(Vec b, Vec x, double atol)
{
  const double volume = grid_.cellVolume();
  VP_CALL(VecScale(b, volume));
  VP_CALL(MatNullSpaceRemove(nullSpace_, b));
  if (direct_) {
    VP_CALL(KSPSolve(ksp_, b, x));
    return 1;
  }
  if (history_) {
    history_->start(b, x);
  } else {
    // The previous solution is a good start for smooth flows, a bad one after an impulsive change
    // (e.g. a lid set in motion): keep it only if it beats zero.
    PetscReal bnorm, r0;
    VP_CALL(MatMult(matrix(), x, work_));
    VP_CALL(VecAYPX(work_, -1.0, b));
    VP_CALL(VecNorm(work_, NORM_2, &r0));
    VP_CALL(VecNorm(b, NORM_2, &bnorm));
    if (r0 > bnorm) VP_CALL(VecSet(x, 0));
  }
  if (!userAtol_) VP_CALL(KSPSetTolerances(ksp_, PETSC_DEFAULT, atol * volume, PETSC_DEFAULT, PETSC_DEFAULT));
  VP_CALL(KSPSolve(ksp_, b, x));
  KSPConvergedReason reason;
  VP_CALL(KSPGetConvergedReason(ksp_, &reason));
  PetscInt its, retryIts = 0;
  VP_CALL(KSPGetIterationNumber(ksp_, &its));
  if (history_ && (reason == KSP_DIVERGED_INDEFINITE_PC || reason == KSP_DIVERGED_INDEFINITE_MAT ||
                   reason == KSP_DIVERGED_BREAKDOWN)) {
    // A fitted start can leave a residual near round-off, where CG breaks down (measured: a steady
    // Stokes flow round a sphere, DIVERGED_INDEFINITE_PC at 1.4e-6 of ||b||): start again from zero.
    VP_CALL(VecSet(x, 0));
    VP_CALL(KSPSolve(ksp_, b, x));
    VP_CALL(KSPGetConvergedReason(ksp_, &reason));
    retryIts = its;
    VP_CALL(KSPGetIterationNumber(ksp_, &its));
  }
  if (reason < 0)
    throw StepFailure(std::string("pressure solve did not converge: ") + KSPConvergedReasons[reason] +
                             " (see -pressure_ksp_monitor, -pressure_ksp_max_it)");
  if (history_) history_->add(x);
  return static_cast<int>(its + retryIts);
}

} // namespace vp
