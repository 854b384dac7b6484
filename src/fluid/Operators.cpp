#include "vp/fluid/Operators.hpp"
#include "vp/grid/Boundary.hpp"
#include <cmath>

namespace vp::ops {

namespace {

constexpr PetscInt E[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

inline PetscScalar at(PetscScalar**** u, PetscInt i, PetscInt j, PetscInt k, int c) { return u[k][j][i][c]; }

// Loops over the owned cells (k, j, i).
template <class F>
void forOwned(const Grid& g, F&& f)
{
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) f(i, j, k);
}

} // namespace

void advectionAndLaplacian(const Grid& g, PetscScalar**** u, PetscScalar**** N, PetscScalar**** L)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  const double ih2[3] = {ih[0] * ih[0], ih[1] * ih[1], ih[2] * ih[2]};
  forOwned(g, [&](PetscInt i, PetscInt j, PetscInt k) {
    const PetscInt p[3] = {i, j, k};
    for (int c = 0; c < 3; ++c) {
      if (isFixedFace(g, c, p[c])) continue;
      const PetscScalar uc = at(u, i, j, k, c);
      double adv = 0, lap = 0;
      for (int d = 0; d < 3; ++d) {
        const PetscInt* e = E[d];
        const PetscScalar up = at(u, i + e[0], j + e[1], k + e[2], c);
        const PetscScalar um = at(u, i - e[0], j - e[1], k - e[2], c);
        lap += (up - 2 * uc + um) * ih2[d];
        if (d == c) {
          // Momentum flux through the cell centres on either side of the face.
          const double fp = 0.5 * (uc + up), fm = 0.5 * (um + uc);
          adv += (fp * fp - fm * fm) * ih[d];
        } else {
          // Flux through the two edges (c-face, d-face) of the face's control volume.
          const PetscInt* ec = E[c];
          const double vp = 0.5 * (at(u, i + e[0], j + e[1], k + e[2], d) +
                                   at(u, i + e[0] - ec[0], j + e[1] - ec[1], k + e[2] - ec[2], d));
          const double vm = 0.5 * (at(u, i, j, k, d) + at(u, i - ec[0], j - ec[1], k - ec[2], d));
          adv += (vp * 0.5 * (uc + up) - vm * 0.5 * (um + uc)) * ih[d];
        }
      }
      N[k][j][i][c] = adv;
      L[k][j][i][c] = lap;
    }
  });
}

void divergence(const Grid& g, PetscScalar**** u, PetscScalar*** div)
{
  const double ih[3] = {1 / g.h(0), 1 / g.h(1), 1 / g.h(2)};
  forOwned(g, [&](PetscInt i, PetscInt j, PetscInt k) {
    div[k][j][i] = (u[k][j][i + 1][0] - u[k][j][i][0]) * ih[0] + (u[k][j + 1][i][1] - u[k][j][i][1]) * ih[1] +
                   (u[k + 1][j][i][2] - u[k][j][i][2]) * ih[2];
  });
}

void addGradient(const Grid& g, PetscScalar*** phi, double scale, PetscScalar**** out)
{
  const double s[3] = {scale / g.h(0), scale / g.h(1), scale / g.h(2)};
  forOwned(g, [&](PetscInt i, PetscInt j, PetscInt k) {
    const PetscInt p[3] = {i, j, k};
    for (int c = 0; c < 3; ++c) {
      if (isFixedFace(g, c, p[c])) continue;
      const PetscInt* e = E[c];
      out[k][j][i][c] += s[c] * (phi[k][j][i] - phi[k - e[2]][j - e[1]][i - e[0]]);
    }
  });
}

void faceToCentre(const Grid& g, PetscScalar**** u, PetscScalar**** centre)
{
  forOwned(g, [&](PetscInt i, PetscInt j, PetscInt k) {
    centre[k][j][i][0] = 0.5 * (u[k][j][i][0] + u[k][j][i + 1][0]);
    centre[k][j][i][1] = 0.5 * (u[k][j][i][1] + u[k][j + 1][i][1]);
    centre[k][j][i][2] = 0.5 * (u[k][j][i][2] + u[k + 1][j][i][2]);
  });
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
