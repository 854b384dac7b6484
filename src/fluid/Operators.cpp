#include "vp/fluid/Operators.hpp"
#include "vp/core/VectorClones.hpp"
#include "vp/grid/Boundary.hpp"
#include <cmath>
#include <cstddef>
#include <vector>

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

// The convective flux divergence and the Laplacian along a row of the face array, taken element
// by element whatever its component (3 values per face, the DMDA's ghosted layout): every
// neighbour an element needs is at a fixed offset, so the loop reads at unit stride and vectorises
// without shuffles. Each element picks its own terms by its component c = lane[m]: the candidates
// are computed for every element and selected, which costs less than de-interleaving the row.
// oy, oz: the offsets of the next row and plane; the flux of u_c along d through the face's upper
// side is V T, with T = u_c averaged to it and V the d-velocity there (T itself when d = c).
inline void rowTerms(const PetscScalar* __restrict q, const double* __restrict lane, std::ptrdiff_t oy,
                     std::ptrdiff_t oz, const double ih[3], const double ih2[3], PetscScalar* __restrict n,
                     PetscScalar* __restrict l, std::ptrdiff_t count)
{
  // Sums of two values stand for their means: the factor 1/4 of each flux goes into the 1/h.
  const double fx = 0.25 * ih[0], fy = 0.25 * ih[1], fz = 0.25 * ih[2];
#pragma omp simd
  for (std::ptrdiff_t m = 0; m < count; ++m) {
    const PetscScalar* p = q + m;
    const double c = lane[m];
    const double u = p[0], xp = p[3], xm = p[-3], yp = p[oy], ym = p[-oy], zp = p[oz], zm = p[-oz];
    l[m] = (xp - 2 * u + xm) * ih2[0] + (yp - 2 * u + ym) * ih2[1] + (zp - 2 * u + zm) * ih2[2];
    // Upper and lower sides along x, y, z; the d-velocity at each for the components c != d
    // (every candidate is computed: a conditional load would be a masked one).
    const double txp = u + xp, txm = xm + u, typ = u + yp, tym = ym + u, tzp = u + zp, tzm = zm + u;
    const double vxp1 = p[2] + p[2 - oy], vxm1 = p[-1] + p[-1 - oy], vxp2 = p[1] + p[1 - oz], vxm2 = p[-2] + p[-2 - oz];
    const double vyp0 = p[1 + oy] + p[oy - 2], vym0 = p[1] + p[-2], vyp2 = p[oy - 1] + p[oy - 1 - oz], vym2 = p[-1] + p[-1 - oz];
    const double vzp0 = p[2 + oz] + p[oz - 1], vzm0 = p[2] + p[-1], vzp1 = p[1 + oz] + p[1 + oz - oy], vzm1 = p[1] + p[1 - oy];
    const double vxp = c == 0 ? txp : c == 1 ? vxp1 : vxp2, vxm = c == 0 ? txm : c == 1 ? vxm1 : vxm2;
    const double vyp = c == 1 ? typ : c == 0 ? vyp0 : vyp2, vym = c == 1 ? tym : c == 0 ? vym0 : vym2;
    const double vzp = c == 2 ? tzp : c == 0 ? vzp0 : vzp1, vzm = c == 2 ? tzm : c == 0 ? vzm0 : vzm1;
    n[m] = (vxp * txp - vxm * txm) * fx + (vyp * typ - vym * tym) * fy + (vzp * tzp - vzm * tzm) * fz;
  }
}

} // namespace

VP_VECTOR_CLONES void advectionAndLaplacian(const Grid& g, PetscScalar**** u, PetscScalar**** N, PetscScalar**** L)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  const double ih2[3] = {ih[0] * ih[0], ih[1] * ih[1], ih[2] * ih[2]};
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2), nx = g.end(0) - i0, ny = g.end(1) - j0;
  // Rows addressed by arithmetic: the arrays' pointer tables hold a pointer per face, out of cache.
  // N and L are owned-box arrays: rows of 3 nx values, planes of ny rows.
  const PetscScalar* u0 = &u[k0][j0][i0][0];
  const std::ptrdiff_t oy = &u[k0][j0 + 1][i0][0] - u0, oz = &u[k0 + 1][j0][i0][0] - u0, count = 3 * nx;
  PetscScalar *n0 = &N[k0][j0][i0][0], *l0 = &L[k0][j0][i0][0];
  std::vector<double> lane(count);
  for (std::ptrdiff_t m = 0; m < count; ++m) lane[m] = double(m % 3);
  // Fixed (wall) faces get N = L = 0: face 0 of a wall-bounded axis.
  const bool wallX = isFixedFace(g, 0, i0);
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const std::ptrdiff_t row = count * ((k - k0) * ny + (j - j0));
      PetscScalar *n = n0 + row, *l = l0 + row;
      rowTerms(u0 + (j - j0) * oy + (k - k0) * oz, lane.data(), oy, oz, ih, ih2, n, l, count);
      if (wallX) n[0] = l[0] = 0;
      for (int c = 1; c < 3; ++c)
        if (isFixedFace(g, c, c == 1 ? j : k))
          for (std::ptrdiff_t m = c; m < count; m += 3) n[m] = l[m] = 0;
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
