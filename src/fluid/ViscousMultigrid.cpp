#include "vp/fluid/ViscousMultigrid.hpp"
#include "vp/core/VecValues.hpp"
#include "vp/core/VectorClones.hpp"
#include "vp/fluid/DiffusionSolver.hpp"
#include <utility>

namespace vp {

namespace {

// Coarse grids keep at least this many cells per axis (a 2-cell periodic axis still couples).
constexpr int kMinCells = 2;

// x = w dinv b (Jacobi from zero); x local layout, b and dinv global.
VP_VECTOR_CLONES void jacobiFromZero(PetscInt n, double w, const PetscScalar* __restrict b,
                                     const PetscScalar* __restrict dinv, PetscScalar* __restrict x)
{
#pragma omp simd
  for (PetscInt i = 0; i < n; ++i) x[i] = w * dinv[i] * b[i];
}

} // namespace

ViscousMultigrid::ViscousMultigrid(const DiffusionSolver& fine, const Grid& grid, const BoundaryConfig& bc, int levels)
{
  levels_.resize(1);
  levels_[0].grid = &grid;
  levels_[0].op = &fine;
  while (static_cast<int>(levels_.size()) < levels && levels_.back().grid->coarsenable(kMinCells)) {
    Level c;
    c.ownGrid = std::make_unique<Grid>(*levels_.back().grid, Grid::Coarsen{});
    c.ownOp = std::make_unique<DiffusionSolver>(*c.ownGrid, bc, ViscousOperator::Fused);
    c.grid = c.ownGrid.get();
    c.op = c.ownOp.get();
    levels_.push_back(std::move(c));
  }
  for (size_t l = 0; l < levels_.size(); ++l) {
    Level& v = levels_[l];
    DM f = v.grid->faceSolveDM();
    for (Vec* w : {&v.x, &v.x2, &v.rL}) {
      VP_CALL(DMCreateLocalVector(f, w));
      VP_CALL(VecZeroEntries(*w));
    }
    if (l > 0) VP_CALL(DMCreateGlobalVector(f, &v.b));
    if (l > 0) VP_CALL(DMCreateGlobalVector(f, &v.theta));
    if (l + 1 < levels_.size()) VP_CALL(DMCreateLocalVector(f, &v.thetaL));
  }
}

ViscousMultigrid::~ViscousMultigrid()
{
  for (Level& v : levels_) {
    if (v.ownGrid) VecDestroy(&v.b);  // level 0's b is the caller's
    for (Vec* w : {&v.x, &v.x2, &v.rL, &v.theta, &v.thetaL}) VecDestroy(w);
  }
}

void ViscousMultigrid::setOperator(double a, Vec theta)
{
  Vec t = theta;
  for (size_t l = 1; l < levels_.size(); ++l) {
    Level &f = levels_[l - 1], &c = levels_[l];
    if (t) {
      VP_CALL(DMGlobalToLocal(f.grid->faceSolveDM(), t, INSERT_VALUES, f.thetaL));
      restrictTo(l - 1, f.thetaL, c.theta);
      t = c.theta;
    }
    c.ownOp->setOperator(a, theta ? c.theta : nullptr);
  }
}

double ViscousMultigrid::apply(Vec r, Vec z)
{
  levels_[0].b = r;
  const double rz = cycle(0, z);
  levels_[0].b = nullptr;
  return rz;
}

double ViscousMultigrid::cycle(size_t l, Vec out)
{
  Level& v = levels_[l];
  const DiffusionSolver& A = *v.op;
  {
    ReadValues b(v.b), d(A.inverseDiagonal());
    WriteValues x(v.x);
    A.forRows([&](PetscInt o, PetscInt lo, PetscInt len) { jacobiFromZero(len, kOmega, b + o, d + o, x + lo); });
  }
  if (l + 1 == levels_.size()) {  // the coarsest grid: more sweeps
    for (int s = 1; s < kCoarsestSweeps; ++s) {
      A.sweep(v.x, v.b, kOmega, v.x2);
      std::swap(v.x, v.x2);
    }
    return 0;
  }
  // The residual to the coarse grid, its correction back.
  Level& c = levels_[l + 1];
  A.sweep(v.x, v.b, 0, v.rL);
  A.refreshGhosts(v.rL);
  restrictTo(l, v.rL, c.b);
  cycle(l + 1, nullptr);
  c.op->refreshGhosts(c.x);
  prolongAdd(l, c.x, v.x);
  // The same Jacobi sweep after as before: the cycle stays symmetric.
  if (out) return A.sweep(v.x, v.b, kOmega, out);
  A.sweep(v.x, v.b, kOmega, v.x2);
  std::swap(v.x, v.x2);
  return 0;
}

// Offsets into a level's local (ghosted) and global arrays of face (i, j, k), component 0.
struct Layout {
  PetscInt gs[3], gm[3], xs[3], xm[3];
  explicit Layout(DM da)
  {
    VP_CALL(DMDAGetGhostCorners(da, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
    VP_CALL(DMDAGetCorners(da, &xs[0], &xs[1], &xs[2], &xm[0], &xm[1], &xm[2]));
  }
  PetscInt local(PetscInt i, PetscInt j, PetscInt k) const { return 3 * (((k - gs[2]) * gm[1] + j - gs[1]) * gm[0] + i - gs[0]); }
  PetscInt global(PetscInt i, PetscInt j, PetscInt k) const { return 3 * (((k - xs[2]) * xm[1] + j - xs[1]) * xm[0] + i - xs[0]); }
};

void ViscousMultigrid::restrictTo(size_t fine, Vec fineLocal, Vec coarseGlobal) const
{
  const Grid& gc = *levels_[fine + 1].grid;
  const Layout lf(levels_[fine].grid->faceSolveDM()), lc(gc.faceSolveDM());
  ReadValues fv(fineLocal);
  WriteValues cv(coarseGlobal);
  const PetscInt I0 = gc.start(0), nI = gc.end(0) - I0;
  for (PetscInt K = gc.start(2); K < gc.end(2); ++K)
    for (PetscInt J = gc.start(1); J < gc.end(1); ++J) {
      // row(dj, dk): the fine row 2J + dj, 2K + dk (dj, dk in -1..1), from its face 2 I0.
      auto row = [&](int dj, int dk) { return fv + lf.local(2 * I0, 2 * J + dj, 2 * K + dk); };
      const PetscScalar *r00 = row(0, 0), *r10 = row(1, 0), *r01 = row(0, 1), *r11 = row(1, 1);
      const PetscScalar *rm0 = row(-1, 0), *rm1 = row(-1, 1), *r0m = row(0, -1), *r1m = row(1, -1);
      PetscScalar* c = cv + lc.global(I0, J, K);
      for (PetscInt I = 0; I < nI; ++I) {
        const PetscInt e = 6 * I, w = e - 3, o = e + 3;  // fine faces 2I (even), 2I - 1, 2I + 1
        // x: full weighting along x over 2I-1, 2I, 2I+1; average over the four (j, k) cells.
        auto xs = [&](const PetscScalar* r) { return 0.25 * r[w] + 0.5 * r[e] + 0.25 * r[o]; };
        c[3 * I] = 0.25 * (xs(r00) + xs(r10) + xs(r01) + xs(r11));
        // y: full weighting along y over rows 2J-1, 2J, 2J+1; average over (i, k).
        auto ys = [&](const PetscScalar* r) { return r[e + 1] + r[o + 1]; };
        c[3 * I + 1] = 0.25 * (0.25 * (ys(rm0) + ys(rm1)) + 0.5 * (ys(r00) + ys(r01)) + 0.25 * (ys(r10) + ys(r11)));
        // z: full weighting along z over rows 2K-1, 2K, 2K+1; average over (i, j).
        auto zs = [&](const PetscScalar* r) { return r[e + 2] + r[o + 2]; };
        c[3 * I + 2] = 0.25 * (0.25 * (zs(r0m) + zs(r1m)) + 0.5 * (zs(r00) + zs(r10)) + 0.25 * (zs(r01) + zs(r11)));
      }
    }
  // The fixed wall faces of the coarse grid stay zero.
  levels_[fine + 1].op->forFixedFaces([&](PetscInt o) { cv[o] = 0; });
}

void ViscousMultigrid::prolongAdd(size_t fine, Vec coarseLocal, Vec fineLocal) const
{
  const Grid& gf = *levels_[fine].grid;
  const Layout lf(gf.faceSolveDM()), lc(levels_[fine + 1].grid->faceSolveDM());
  ReadValues cv(coarseLocal);
  WriteValues fv(fineLocal);
  const PetscInt I0 = gf.start(0) / 2, nI = gf.end(0) / 2 - I0;
  for (PetscInt k = gf.start(2); k < gf.end(2); ++k)
    for (PetscInt j = gf.start(1); j < gf.end(1); ++j) {
      const PetscInt J = j / 2, K = k / 2;
      // The coarse rows under this fine row (from face I0); along y (z) an odd fine row lies
      // between two.
      const PetscScalar* c = cv + lc.local(I0, J, K);
      const PetscScalar* cy = cv + lc.local(I0, J + (j % 2), K);
      const PetscScalar* cz = cv + lc.local(I0, J, K + (k % 2));
      PetscScalar* f = fv + lf.local(2 * I0, j, k);
      for (PetscInt I = 0; I < nI; ++I) {
        const PetscInt e = 6 * I, o = e + 3, C = 3 * I;
        f[e] += c[C];
        f[o] += 0.5 * (c[C] + c[C + 3]);
        const double y = 0.5 * (c[C + 1] + cy[C + 1]), z = 0.5 * (c[C + 2] + cz[C + 2]);
        f[e + 1] += y;
        f[o + 1] += y;
        f[e + 2] += z;
        f[o + 2] += z;
      }
    }
}

} // namespace vp
