#include "vp/fluid/Operators.hpp"
#include "vp/core/VectorClones.hpp"
#include "vp/grid/Boundary.hpp"
#include <cmath>
#include <cstddef>

namespace vp::ops {

namespace {

constexpr PetscInt E[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// Loops over the owned cells (k, j, i).
template <class F>
void forOwned(const Grid& g, F&& f)
{
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) f(i, j, k);
}

// The convective flux divergence and the Laplacian of component C along a row of `count` faces
// starting at q, with o[d] the offset of the next face along axis d (3 values per face, the DMDA's
// ghosted layout). One component per loop keeps the body uniform, so the loop vectorises.
template <int C>
inline void rowTerms(const PetscScalar* __restrict q, const std::ptrdiff_t o[3], const double ih[3],
                     const double ih2[3], PetscScalar* __restrict n, PetscScalar* __restrict l, PetscInt count)
{
  const std::ptrdiff_t o0 = o[0], o1 = o[1], o2 = o[2], oc = o[C];
#pragma omp simd
  for (PetscInt i = 0; i < count; ++i) {
    const PetscScalar* f = q + 3 * i;
    const double uc = f[C];
    double adv = 0, lap = 0;
    for (int d = 0; d < 3; ++d) {
      const std::ptrdiff_t od = d == 0 ? o0 : d == 1 ? o1 : o2;
      const double up = f[C + od], um = f[C - od];
      lap += (up - 2 * uc + um) * ih2[d];
      if (d == C) {
        // Momentum flux through the cell centres on either side of the face.
        const double fp = 0.5 * (uc + up), fm = 0.5 * (um + uc);
        adv += (fp * fp - fm * fm) * ih[d];
      } else {
        // Flux through the two edges (C-face, d-face) of the face's control volume.
        const double vp = 0.5 * (f[d + od] + f[d + od - oc]);
        const double vm = 0.5 * (f[d] + f[d - oc]);
        adv += (vp * 0.5 * (uc + up) - vm * 0.5 * (um + uc)) * ih[d];
      }
    }
    n[3 * i + C] = adv;
    l[3 * i + C] = lap;
  }
}

} // namespace

VP_VECTOR_CLONES void advectionAndLaplacian(const Grid& g, PetscScalar**** u, PetscScalar**** N, PetscScalar**** L)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  const double ih2[3] = {ih[0] * ih[0], ih[1] * ih[1], ih[2] * ih[2]};
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2);
  // Offsets of the neighbouring faces in the ghosted array (rows are contiguous along x).
  const std::ptrdiff_t o[3] = {3, &u[k0][j0 + 1][i0][0] - &u[k0][j0][i0][0], &u[k0 + 1][j0][i0][0] - &u[k0][j0][i0][0]};
  // Fixed (wall) faces keep N = L = 0: face 0 of a wall-bounded axis.
  const PetscInt iFree = isFixedFace(g, 0, i0) ? i0 + 1 : i0;
  // Rows addressed by arithmetic: the arrays' pointer tables hold a pointer per face, out of cache.
  // N and L are owned-box arrays: rows of 3 nx values, planes of ny rows.
  const PetscInt nx = g.end(0) - i0, ny = g.end(1) - j0, skip = iFree - i0;
  const PetscScalar* u0 = &u[k0][j0][i0][0];
  PetscScalar *n0 = &N[k0][j0][i0][0], *l0 = &L[k0][j0][i0][0];
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const bool free1 = !isFixedFace(g, 1, j), free2 = !isFixedFace(g, 2, k);
      const PetscScalar* q = u0 + (j - j0) * o[1] + (k - k0) * o[2];
      const std::ptrdiff_t row = 3 * nx * ((k - k0) * ny + (j - j0));
      PetscScalar *n = n0 + row, *l = l0 + row;
      rowTerms<0>(q + 3 * skip, o, ih, ih2, n + 3 * skip, l + 3 * skip, nx - skip);
      if (free1) rowTerms<1>(q, o, ih, ih2, n, l, nx);
      if (free2) rowTerms<2>(q, o, ih, ih2, n, l, nx);
    }
}

void divergence(const Grid& g, PetscScalar**** u, PetscScalar*** div)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2), nx = g.end(0) - i0;
  const std::ptrdiff_t sy = &u[k0][j0 + 1][i0][0] - &u[k0][j0][i0][0], sz = &u[k0 + 1][j0][i0][0] - &u[k0][j0][i0][0];
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const PetscScalar* q = &u[k][j][i0][0];
      PetscScalar* d = &div[k][j][i0];
      for (PetscInt i = 0; i < nx; ++i, q += 3)
        d[i] = (q[3] - q[0]) * ih[0] + (q[sy + 1] - q[1]) * ih[1] + (q[sz + 2] - q[2]) * ih[2];
    }
}

void addGradient(const Grid& g, PetscScalar*** phi, double scale, PetscScalar**** out, PetscScalar**** weight)
{
  const double s[3] = {scale / g.h(0), scale / g.h(1), scale / g.h(2)};
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2), nx = g.end(0) - i0;
  const std::ptrdiff_t py = &phi[k0][j0 + 1][i0] - &phi[k0][j0][i0], pz = &phi[k0 + 1][j0][i0] - &phi[k0][j0][i0];
  // Fixed (wall) faces keep their value: face 0 of a wall-bounded axis.
  const PetscInt iFree = isFixedFace(g, 0, i0) ? 1 : 0;
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const PetscScalar* p = &phi[k][j][i0];
      PetscScalar* o = &out[k][j][i0][0];
      const PetscScalar* w = weight ? &weight[k][j][i0][0] : nullptr;
      auto add = [&](int c, std::ptrdiff_t stride, PetscInt from) {
        if (w)
          for (PetscInt i = from; i < nx; ++i) o[3 * i + c] += s[c] * w[3 * i + c] * (p[i] - p[i - stride]);
        else
          for (PetscInt i = from; i < nx; ++i) o[3 * i + c] += s[c] * (p[i] - p[i - stride]);
      };
      add(0, 1, iFree);
      if (!isFixedFace(g, 1, j)) add(1, py, 0);
      if (!isFixedFace(g, 2, k)) add(2, pz, 0);
    }
}

void faceToCentre(const Grid& g, PetscScalar**** u, PetscScalar**** centre)
{
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2), nx = g.end(0) - i0;
  const std::ptrdiff_t sy = &u[k0][j0 + 1][i0][0] - &u[k0][j0][i0][0], sz = &u[k0 + 1][j0][i0][0] - &u[k0][j0][i0][0];
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const PetscScalar* q = &u[k][j][i0][0];
      PetscScalar* c = &centre[k][j][i0][0];
      for (PetscInt i = 0; i < nx; ++i, q += 3, c += 3) {
        c[0] = 0.5 * (q[0] + q[3]);
        c[1] = 0.5 * (q[1] + q[sy + 1]);
        c[2] = 0.5 * (q[2] + q[sz + 2]);
      }
    }
}

FieldStats stats(const Grid& g, PetscScalar**** u)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  double maxDiv = 0, ke = 0, rate = 0, sum[3] = {0, 0, 0};
  forOwned(g, [&](PetscInt i, PetscInt j, PetscInt k) {
    double div = 0;
    for (int c = 0; c < 3; ++c) {
      const PetscInt* e = E[c];
      const double uc = u[k][j][i][c];
      div += (u[k + e[2]][j + e[1]][i + e[0]][c] - uc) * ih[c];
      ke += uc * uc;
      sum[c] += uc;
      rate = std::max(rate, std::fabs(uc) * ih[c]);
    }
    maxDiv = std::max(maxDiv, std::fabs(div));
  });
  // Wall axes have one more face than cells: the face N (ghost) holds the wall's normal velocity.
  for (int c = 0; c < 3; ++c) {
    if (!g.atHigh(c)) continue;
    PetscInt lo[3] = {g.start(0), g.start(1), g.start(2)}, hi[3] = {g.end(0), g.end(1), g.end(2)};
    lo[c] = g.n(c);
    hi[c] = g.n(c) + 1;
    for (PetscInt k = lo[2]; k < hi[2]; ++k)
      for (PetscInt j = lo[1]; j < hi[1]; ++j)
        for (PetscInt i = lo[0]; i < hi[0]; ++i) {
          ke += u[k][j][i][c] * u[k][j][i][c];
          rate = std::max(rate, std::fabs(u[k][j][i][c]) * ih[c]);
        }
  }
  double local[3] = {maxDiv, rate, 0}, global[3];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, g.comm());
  // Energy and mean over the faces of the owned cells (face 0 of each cell: one face per cell).
  double sums[4] = {ke, sum[0], sum[1], sum[2]}, sumsGlobal[4];
  MPI_Allreduce(sums, sumsGlobal, 4, MPI_DOUBLE, MPI_SUM, g.comm());
  const double keGlobal = sumsGlobal[0];
  FieldStats s;
  s.maxDivergence = global[0];
  s.maxRate = global[1];
  s.kineticEnergy = 0.5 * keGlobal * g.cellVolume();
  s.meanVelocity = Vec3{sumsGlobal[1], sumsGlobal[2], sumsGlobal[3]} / double(g.cells());
  return s;
}

} // namespace vp::ops
