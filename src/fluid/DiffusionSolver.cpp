#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/OptionDefaults.hpp"
#include "vp/core/VecValues.hpp"
#include "vp/core/VectorClones.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/fluid/ViscousMultigrid.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace vp {

DiffusionSolver::DiffusionSolver(const Grid& grid, const BoundaryConfig& bc, ViscousOperator op, int mgLevels)
  : grid_(grid), bc_(bc), ghosts_(grid.faceSolveDM())
{
  assembled_ = op == ViscousOperator::Assembled;
  fused_ = op == ViscousOperator::Fused;
  setOptionDefault("-velocity_ksp_type", "cg");
  setOptionDefault("-velocity_pc_type", "jacobi");
  setOptionDefault("-velocity_ksp_norm_type", "unpreconditioned");
  // Measured (docs/fluid.md, tolerances): results change by < 1e-7 relative to rtol 1e-10.
  setOptionDefault("-velocity_ksp_rtol", "1e-6");
  PetscBool set;
  VP_CALL(PetscOptionsHasName(nullptr, "velocity_", "-ksp_atol", &set));
  userAtol_ = set;
  DM f = grid.faceSolveDM();
  for (Vec* v : {&S_, &SdiagL_}) VP_CALL(DMCreateGlobalVector(f, v));
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
  // S is 1 except next to no-slip walls: the faces where it is not, and each row's unit middle.
  {
    ReadValues s(S_);
    forRows([&](PetscInt o, PetscInt, PetscInt len) {
      PetscInt lo = 0, hi = len;
      for (PetscInt n = 0; n < len; ++n) {
        if (s[o + n] == 1) continue;
        weighted_.push_back(o + n);
        if (n < len / 2) lo = n + 1;
        else hi = std::min(hi, n);
      }
      unitS_.push_back({lo, std::max(lo, hi)});
    });
  }
  if (assembled_) {
    assemble();
    VP_CALL(MatDuplicate(SL_, MAT_DO_NOT_COPY_VALUES, &A_));
    VP_CALL(DMCreateGlobalVector(f, &diag_));
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
  if (fused_) {
    // The fused solver is CG + Jacobi (or the multigrid); the KSP only holds the tolerances then.
    KSPType kt;
    PCType pt;
    PC pc;
    VP_CALL(KSPGetType(ksp_, &kt));
    VP_CALL(KSPGetPC(ksp_, &pc));
    VP_CALL(PCGetType(pc, &pt));
    if (std::string(kt) != KSPCG || std::string(pt) != PCJACOBI)
      throw InputError(std::string("option -velocity_operator: fused is CG + Jacobi; for -velocity_ksp_type ") + kt +
                       " -velocity_pc_type " + pt + " choose -velocity_operator shell (or assembled)");
    for (Vec* v : {&r_, &q_, &dinv_}) VP_CALL(DMCreateGlobalVector(f, v));
    if (mgLevels > 1) {
      mg_ = std::make_unique<ViscousMultigrid>(*this, grid, bc, mgLevels);
      if (mg_->levels() < 2) mg_.reset();  // the grid cannot be halved: Jacobi
      else VP_CALL(DMCreateLocalVector(f, &z_));
    }
  }
}

DiffusionSolver::~DiffusionSolver()
{
  KSPDestroy(&ksp_);
  mg_.reset();
  for (Vec* v : {&S_, &SdiagL_, &diag_, &xL_, &r_, &q_, &dinv_, &z_}) VecDestroy(v);
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

DiffusionSolver::Weights DiffusionSolver::weights(const PetscInt gm[3]) const
{
  Weights w;
  for (int d = 0; d < 3; ++d) w.w[d] = a_ / (grid_.h(d) * grid_.h(d));
  w.centre = 1 + 2 * (w.w[0] + w.w[1] + w.w[2]);
  w.stride[0] = 3;
  w.stride[1] = 3 * gm[0];
  w.stride[2] = 3 * gm[0] * gm[1];
  return w;
}

// y = S (1 + theta) x - a S L x over [b, e) of a grid row (S null: 1 there); x ghosted, theta may
// be null. __restrict: y never aliases x, S or theta, so the compiler may vectorise the row.
VP_VECTOR_CLONES void DiffusionSolver::stencilRange(PetscInt b, PetscInt e, const Weights& w, const PetscScalar* __restrict xr,
                                                    const PetscScalar* __restrict sr, const PetscScalar* __restrict tr,
                                                    PetscScalar* __restrict yr)
{
  const double wx = w.w[0], wy = w.w[1], wz = w.w[2], wc = w.centre;
  const PetscInt sx = w.stride[0], sy = w.stride[1], sz = w.stride[2];
  // The centre term minus the neighbours', in this order on every path (bitwise the same sums).
  auto minusNeighbours = [&](PetscInt n, double centre) {
    return centre - wx * (xr[n + sx] + xr[n - sx]) - wy * (xr[n + sy] + xr[n - sy]) - wz * (xr[n + sz] + xr[n - sz]);
  };
  if (sr && tr) {
    for (PetscInt n = b; n < e; ++n) yr[n] = sr[n] * minusNeighbours(n, (wc + tr[n]) * xr[n]);
  } else if (sr) {
    for (PetscInt n = b; n < e; ++n) yr[n] = sr[n] * minusNeighbours(n, wc * xr[n]);
  } else if (tr) {
    for (PetscInt n = b; n < e; ++n) yr[n] = minusNeighbours(n, (wc + tr[n]) * xr[n]);
  } else {
    for (PetscInt n = b; n < e; ++n) yr[n] = minusNeighbours(n, wc * xr[n]);
  }
}

// One grid row (number r of this rank's rows): S is read only outside the row's unit middle, theta
// only where the row has particles.
void DiffusionSolver::stencilRow(PetscInt r, PetscInt len, const Weights& w, const PetscScalar* xr, const PetscScalar* sr,
                                 const PetscScalar* tr, PetscScalar* yr) const
{
  const auto [lo, hi] = unitS_[r];
  const auto [t0, t1] = tr ? thetaRows_[r] : std::pair<PetscInt, PetscInt>{0, 0};
  PetscInt cut[6] = {0, lo, hi, t0, t1, len};
  std::sort(cut, cut + 6);
  for (int k = 0; k < 5; ++k) {
    const PetscInt b = cut[k], e = cut[k + 1];
    if (b == e) continue;
    stencilRange(b, e, w, xr, b < lo || b >= hi ? sr : nullptr, b >= t0 && b < t1 ? tr : nullptr, yr);
  }
}

void DiffusionSolver::markTheta(Vec theta)
{
  thetaRows_.clear();
  if (!theta) return;
  ReadValues th(theta);
  forRows([&](PetscInt o, PetscInt, PetscInt len) {
    PetscInt t0 = 0, t1 = len;
    while (t0 < len && th[o + t0] == 0) ++t0;
    while (t1 > t0 && th[o + t1 - 1] == 0) --t1;
    thetaRows_.push_back({t0, t1});
  });
}

namespace {

// out = b - y (omega 0: the residual; returns 0), else out = x + omega dinv (b - y) (a damped
// Jacobi sweep; returns b.out).
VP_VECTOR_CLONES double jacobiRow(PetscInt n, double omega, const PetscScalar* __restrict x, const PetscScalar* __restrict y,
                                  const PetscScalar* __restrict b, const PetscScalar* __restrict dinv, PetscScalar* __restrict out)
{
  double bo = 0;
  if (omega == 0) {
#pragma omp simd
    for (PetscInt i = 0; i < n; ++i) out[i] = b[i] - y[i];
    return 0;
  }
#pragma omp simd reduction(+ : bo)
  for (PetscInt i = 0; i < n; ++i) {
    out[i] = x[i] + omega * dinv[i] * (b[i] - y[i]);
    bo += b[i] * out[i];
  }
  return bo;
}

} // namespace

double DiffusionSolver::sweep(Vec x, Vec b, double omega, Vec out) const
{
  const Grid& g = grid_;
  refreshGhosts(x);
  PetscInt gs[3], gm[3];
  VP_CALL(DMDAGetGhostCorners(g.faceSolveDM(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const Weights w = weights(gm);
  ReadValues xl(x), bv(b), sv(S_), dv(dinv_);
  const PetscScalar* th = nullptr;
  if (theta_) VP_CALL(VecGetArrayRead(theta_, &th));
  WriteValues ov(out);
  std::vector<PetscScalar> y(3 * (g.end(0) - g.start(0)));  // one row of A x, kept in cache
  double bo = 0;
  PetscInt r = 0;
  forRows([&](PetscInt o, PetscInt l, PetscInt len) {
    stencilRow(r++, len, w, xl + l, sv + o, th ? th + o : nullptr, y.data());
    bo += jacobiRow(len, omega, xl + l, y.data(), bv + o, dv + o, ov + l);
  });
  if (th) VP_CALL(VecRestoreArrayRead(theta_, &th));
  return bo;
}

void DiffusionSolver::refreshGhosts(Vec local) const
{
  if (grid_.exchangesGhosts()) ghosts_.apply(local);
  FaceArray xa(grid_.faceSolveDM(), local);
  fillFaceGhosts(grid_, bc_, xa.a, true);
}

int DiffusionSolver::multigridLevels() const { return mg_ ? mg_->levels() : 1; }

// y = S (1 + theta) x - a S L x in one sweep over the ghosted x. Every face component has the same
// 7-point form once the wall ghosts hold the homogeneous boundary rules (Boundary.hpp), so a grid
// row of 3 xm values is one contiguous, vectorisable loop; fixed wall faces are identity rows.
VP_VECTOR_CLONES double DiffusionSolver::apply(Vec x, Vec y, bool dot, bool local)
{
  const Grid& g = grid_;
  DM f = g.faceSolveDM();
  const Vec xLocal = local ? x : xL_;
  if (local) {
    refreshGhosts(x);
  } else {
    VP_CALL(DMGlobalToLocal(f, x, INSERT_VALUES, xL_));
    FaceArray xa(f, xLocal);
    fillFaceGhosts(g, bc_, xa.a, true);
  }
  PetscInt gs[3], gm[3];
  VP_CALL(DMDAGetGhostCorners(f, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscScalar *xl, *xg = nullptr, *s, *th = nullptr;
  PetscScalar* ya;
  VP_CALL(VecGetArrayRead(xLocal, &xl));
  // The ghost fill zeroes the fixed faces in the local array: a global x's rows read its own values.
  if (!local) VP_CALL(VecGetArrayRead(x, &xg));
  VP_CALL(VecGetArrayRead(S_, &s));
  if (theta_) VP_CALL(VecGetArrayRead(theta_, &th));
  VP_CALL(VecGetArray(y, &ya));
  const Weights w = weights(gm);
  const PetscInt sx = 3, sy = 3 * gm[0], sz = 3 * gm[0] * gm[1];
  const PetscInt row = 3 * (g.end(0) - g.start(0));
  double xy = 0;
  PetscInt o = 0, r = 0;  // owned (global-vector) offset and number of the row
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j, o += row, ++r) {
      const PetscScalar* xr = xl + (k - gs[2]) * sz + (j - gs[1]) * sy + (g.start(0) - gs[0]) * sx;
      stencilRow(r, row, w, xr, s + o, th ? th + o : nullptr, ya + o);
      const PetscScalar* yr = ya + o;
      if (dot) {  // the row is still in cache; a local x is zero on the fixed faces (fusedSolve)
        double sum = 0;
#pragma omp simd reduction(+ : sum)
        for (PetscInt n = 0; n < row; ++n) sum += xr[n] * yr[n];
        xy += sum;
      }
    }
  // Decoupled rows (1 + theta) x of the fixed wall faces (their increment is zero).
  forFixedFaces([&](PetscInt o) { ya[o] = local ? 0.0 : (th ? 1 + th[o] : 1) * xg[o]; });
  VP_CALL(VecRestoreArray(y, &ya));
  if (th) VP_CALL(VecRestoreArrayRead(theta_, &th));
  VP_CALL(VecRestoreArrayRead(S_, &s));
  if (!local) VP_CALL(VecRestoreArrayRead(x, &xg));
  VP_CALL(VecRestoreArrayRead(xLocal, &xl));
  return xy;
}

PetscErrorCode DiffusionSolver::mult(Mat A, Vec x, Vec y)
{
  DiffusionSolver* self;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &self));
  self->apply(x, y, false);
  PetscFunctionReturn(0);
}

namespace {

// diag = S (1 + theta) - a S diag(L); 1 + theta on fixed faces (S = 1, diag(L) = 0 there).
inline double diagonalEntry(double s, double theta, double a, double sDiagL) { return s * (1 + theta) - a * sDiagL; }

} // namespace

PetscErrorCode DiffusionSolver::diagonal(Mat A, Vec d)
{
  DiffusionSolver* self;
  PetscInt n;
  const PetscScalar *s, *sd, *th = nullptr;
  PetscScalar* y;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &self));
  PetscCall(VecGetLocalSize(d, &n));
  PetscCall(VecGetArrayRead(self->S_, &s));
  PetscCall(VecGetArrayRead(self->SdiagL_, &sd));
  if (self->theta_) PetscCall(VecGetArrayRead(self->theta_, &th));
  PetscCall(VecGetArray(d, &y));
  for (PetscInt i = 0; i < n; ++i) y[i] = diagonalEntry(s[i], th ? th[i] : 0, self->a_, sd[i]);
  PetscCall(VecRestoreArray(d, &y));
  if (th) PetscCall(VecRestoreArrayRead(self->theta_, &th));
  PetscCall(VecRestoreArrayRead(self->SdiagL_, &sd));
  PetscCall(VecRestoreArrayRead(self->S_, &s));
  PetscFunctionReturn(0);
}

void DiffusionSolver::setOperator(double a, Vec theta)
{
  a_ = a;
  theta_ = theta;
  markTheta(theta);
  if (assembled_) {
    // A = S (1 + theta) - a S L; the pattern is that of S L, so the preconditioner is rebuilt in place.
    VP_CALL(MatCopy(SL_, A_, SAME_NONZERO_PATTERN));
    VP_CALL(MatScale(A_, -a));
    if (theta) {
      VP_CALL(VecPointwiseMult(diag_, S_, theta));
      VP_CALL(VecAXPY(diag_, 1.0, S_));
    } else {
      VP_CALL(VecCopy(S_, diag_));
    }
    VP_CALL(MatDiagonalSet(A_, diag_, ADD_VALUES));
  } else if (fused_) {
    // dinv = 1 / diag in one pass.
    PetscInt n;
    VP_CALL(VecGetLocalSize(dinv_, &n));
    ReadValues s(S_), sd(SdiagL_);
    const PetscScalar* th = nullptr;
    if (theta) VP_CALL(VecGetArrayRead(theta, &th));
    WriteValues d(dinv_);
    for (PetscInt i = 0; i < n; ++i) d[i] = 1 / diagonalEntry(s[i], th ? th[i] : 0, a, sd[i]);
    if (th) VP_CALL(VecRestoreArrayRead(theta, &th));
    if (mg_) mg_->setOperator(a, theta);
    return;
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
  {
    WriteValues rv(r);
    ReadValues sv(S_);
    for (const PetscInt f : weighted_) rv[f] *= sv[f];  // r = S r (S is 1 elsewhere)
  }
  if (!userAtol_) VP_CALL(KSPSetTolerances(ksp_, PETSC_DEFAULT, atol, PETSC_DEFAULT, PETSC_DEFAULT));
  if (fused_) return fusedSolve(r, du, atol);
  VP_CALL(KSPSolve(ksp_, r, du));
  KSPConvergedReason reason;
  VP_CALL(KSPGetConvergedReason(ksp_, &reason));
  if (reason < 0)
    throw StepFailure(std::string("velocity (diffusion) solve did not converge: ") +
                             KSPConvergedReasons[reason] + " (see -velocity_ksp_monitor)");
  PetscInt its;
  VP_CALL(KSPGetIterationNumber(ksp_, &its));
  return static_cast<int>(its);
}

// The vector passes of the fused CG (restrict: the arrays never alias; simd reductions: the dot
// products vectorise, summed in a fixed order for a given build).
namespace {

VP_VECTOR_CLONES void initialResidual(PetscInt n, const PetscScalar* __restrict b, const PetscScalar* __restrict ax,
                     const PetscScalar* __restrict dinv, PetscScalar* __restrict r, PetscScalar* __restrict p,
                     double sums[3])
{
  double rz = 0, rr = 0, bb = 0;
#pragma omp simd reduction(+ : rz, rr, bb)
  for (PetscInt i = 0; i < n; ++i) {
    r[i] = b[i] - ax[i];
    p[i] = dinv[i] * r[i];
    rz += r[i] * p[i];
    rr += r[i] * r[i];
    bb += b[i] * b[i];
  }
  sums[0] = rz;
  sums[1] = rr;
  sums[2] = bb;
}

// r -= alpha q; sums r.D^-1 r and r.r. (x takes alpha p in the next pass, which reads p anyway.)
VP_VECTOR_CLONES void update(PetscInt n, double alpha, const PetscScalar* __restrict ap, const PetscScalar* __restrict dinv,
                             PetscScalar* __restrict r, double sums[2])
{
  double rz = 0, rr = 0;
#pragma omp simd reduction(+ : rz, rr)
  for (PetscInt i = 0; i < n; ++i) {
    r[i] -= alpha * ap[i];
    rz += r[i] * dinv[i] * r[i];
    rr += r[i] * r[i];
  }
  sums[0] = rz;
  sums[1] = rr;
}

// x += alpha p, then p = D^-1 r + beta p.
VP_VECTOR_CLONES void newDirection(PetscInt n, double alpha, double beta, const PetscScalar* __restrict r,
                                   const PetscScalar* __restrict dinv, PetscScalar* __restrict x, PetscScalar* __restrict p)
{
#pragma omp simd
  for (PetscInt i = 0; i < n; ++i) {
    x[i] += alpha * p[i];
    p[i] = dinv[i] * r[i] + beta * p[i];
  }
}

// x += alpha p.
VP_VECTOR_CLONES void lastStep(PetscInt n, double alpha, const PetscScalar* __restrict p, PetscScalar* __restrict x)
{
#pragma omp simd
  for (PetscInt i = 0; i < n; ++i) x[i] += alpha * p[i];
}

// The same passes without Jacobi (multigrid: the preconditioner is a separate pass). r = b - Ax;
// sums r.r, b.b.
VP_VECTOR_CLONES void residualSums(PetscInt n, const PetscScalar* __restrict b, const PetscScalar* __restrict ax,
                  PetscScalar* __restrict r, double sums[2])
{
  double rr = 0, bb = 0;
#pragma omp simd reduction(+ : rr, bb)
  for (PetscInt i = 0; i < n; ++i) {
    r[i] = b[i] - ax[i];
    rr += r[i] * r[i];
    bb += b[i] * b[i];
  }
  sums[0] = rr;
  sums[1] = bb;
}

// x += alpha p; r -= alpha q; returns r.r.
VP_VECTOR_CLONES double updateSums(PetscInt n, double alpha, const PetscScalar* __restrict p, const PetscScalar* __restrict ap,
                  PetscScalar* __restrict x, PetscScalar* __restrict r)
{
  double rr = 0;
#pragma omp simd reduction(+ : rr)
  for (PetscInt i = 0; i < n; ++i) {
    x[i] += alpha * p[i];
    r[i] -= alpha * ap[i];
    rr += r[i] * r[i];
  }
  return rr;
}

// p = z + beta p (both in the local layout).
VP_VECTOR_CLONES void newDirectionFrom(PetscInt n, double beta, const PetscScalar* __restrict z, PetscScalar* __restrict p)
{
#pragma omp simd
  for (PetscInt i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
}

} // namespace

int DiffusionSolver::fusedSolve(Vec b, Vec x, double atol)
{
  PetscReal rtol, abstol, dtol;
  PetscInt maxIts;
  VP_CALL(KSPGetTolerances(ksp_, &rtol, &abstol, &dtol, &maxIts));
  if (!userAtol_) abstol = atol;
  PetscInt n;
  VP_CALL(VecGetLocalSize(x, &n));
  const MPI_Comm comm = grid_.comm();
  auto fail = [](const std::string& why) {
    throw StepFailure("velocity (diffusion) solve did not converge: " + why + " (see -velocity_operator shell -velocity_ksp_monitor)");
  };
  // The fixed wall faces' rows are decoupled, (1 + theta) x = b: solved here, so that their
  // residual and direction stay zero (the local direction has zero there after its ghost fill).
  {
    WriteValues xv(x);
    ReadValues bv(b), dv(dinv_);
    forFixedFaces([&](PetscInt o) { xv[o] = bv[o] * dv[o]; });
  }
  // r = b - A x; sums r.r, b.b; with Jacobi also z = D^-1 r in p and r.z in the same pass (the
  // multigrid's z and r.z follow the residual test). p lives in xL_ (the ghosted layout, free once
  // A x is taken): its products need no copy into one.
  apply(x, q_, false);
  double sums[3] = {0, 0, 0};
  if (mg_) {
    ReadValues bv(b), qv(q_);
    WriteValues rv(r_);
    forRows([&](PetscInt o, PetscInt, PetscInt len) {
      double s2[2];
      residualSums(len, bv + o, qv + o, rv + o, s2);
      sums[1] += s2[0];
      sums[2] += s2[1];
    });
  } else {
    ReadValues bv(b), qv(q_), dv(dinv_);
    WriteValues rv(r_), pv(xL_);
    forRows([&](PetscInt o, PetscInt l, PetscInt len) {
      double s3[3];
      initialResidual(len, bv + o, qv + o, dv + o, rv + o, pv + l, s3);
      for (int i = 0; i < 3; ++i) sums[i] += s3[i];
    });
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, comm);
  // PETSc's default test on the unpreconditioned residual: ||r|| <= max(rtol ||b||, atol).
  const double tol = std::max(rtol * std::sqrt(sums[2]), static_cast<double>(abstol));
  if (std::sqrt(sums[1]) <= tol) return 0;
  // The multigrid's r.z (after the residual test: no cycle for a converged start).
  auto precondition = [&] {
    double rz = mg_->apply(r_, z_);
    MPI_Allreduce(MPI_IN_PLACE, &rz, 1, MPI_DOUBLE, MPI_SUM, comm);
    if (!(rz > 0)) fail("the multigrid preconditioner is not positive definite (r.Mr = " + std::to_string(rz) + ")");
    return rz;
  };
  double rz = sums[0];
  if (mg_) {
    rz = precondition();
    VP_CALL(VecCopy(z_, xL_));
  }
  for (PetscInt it = 1; it <= maxIts; ++it) {
    double pq = apply(xL_, q_, true, true);
    MPI_Allreduce(MPI_IN_PLACE, &pq, 1, MPI_DOUBLE, MPI_SUM, comm);
    if (!(pq > 0)) fail("the operator is not positive definite (p.Ap = " + std::to_string(pq) + ")");
    const double alpha = rz / pq;
    // r -= alpha q and x += alpha p (Jacobi: x with the new direction); sums r.D^-1 r (Jacobi), r.r.
    double s2[2] = {0, 0};
    {
      ReadValues pv(xL_), qv(q_), dv(dinv_);
      WriteValues xv(x), rv(r_);
      forRows([&](PetscInt o, PetscInt l, PetscInt len) {
        if (mg_) {
          s2[1] += updateSums(len, alpha, pv + l, qv + o, xv + o, rv + o);
          return;
        }
        double row[2];
        update(len, alpha, qv + o, dv + o, rv + o, row);
        s2[0] += row[0];
        s2[1] += row[1];
      });
    }
    MPI_Allreduce(MPI_IN_PLACE, s2, 2, MPI_DOUBLE, MPI_SUM, comm);
    const double rnorm = std::sqrt(s2[1]);
    if (!std::isfinite(rnorm)) fail("the residual is not finite");
    if (rnorm <= tol) {
      if (!mg_) {
        ReadValues pv(xL_);
        WriteValues xv(x);
        forRows([&](PetscInt o, PetscInt l, PetscInt len) { lastStep(len, alpha, pv + l, xv + o); });
      }
      return static_cast<int>(it);
    }
    // p = z + beta p.
    if (mg_) {
      const double rzNew = precondition();
      const double beta = rzNew / rz;
      rz = rzNew;
      ReadValues zv(z_);
      WriteValues pv(xL_);
      forRows([&](PetscInt, PetscInt l, PetscInt len) { newDirectionFrom(len, beta, zv + l, pv + l); });
      continue;
    }
    const double beta = s2[0] / rz;
    rz = s2[0];
    ReadValues rv(r_), dv(dinv_);
    WriteValues xv(x), pv(xL_);
    forRows([&](PetscInt o, PetscInt l, PetscInt len) { newDirection(len, alpha, beta, rv + o, dv + o, xv + o, pv + l); });
  }
  fail("no convergence in " + std::to_string(maxIts) + " iterations (-velocity_ksp_max_it)");
  return -1;
}

} // namespace vp
