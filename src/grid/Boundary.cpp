#include "vp/grid/Boundary.hpp"
#include "vp/core/Error.hpp"

namespace vp {

namespace {

struct GhostBox {
  PetscInt s[3], e[3];  // ghosted index range [s, e) per axis
};

GhostBox ghostBox(DM dm)
{
  GhostBox b;
  PetscInt m[3];
  VP_CALL(DMDAGetGhostCorners(dm, &b.s[0], &b.s[1], &b.s[2], &m[0], &m[1], &m[2]));
  for (int d = 0; d < 3; ++d) b.e[d] = b.s[d] + m[d];
  return b;
}

// Visits every ghosted (a, b) position of the two axes other than d, with idx[d] left to the caller;
// the lower axis innermost, so that consecutive visits stay close in memory.
template <class F>
void forPlane(const GhostBox& g, int d, F&& f)
{
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  PetscInt idx[3];
  for (idx[b] = g.s[b]; idx[b] < g.e[b]; ++idx[b])
    for (idx[a] = g.s[a]; idx[a] < g.e[a]; ++idx[a]) f(idx);
}

} // namespace

void fillFaceGhosts(const Grid& grid, const BoundaryConfig& bc, PetscScalar**** u, bool homogeneous)
{
  GhostBox g = ghostBox(grid.faceDM());
  auto at = [u](const PetscInt* idx, PetscInt shift, int d, int c) -> PetscScalar& {
    PetscInt i[3] = {idx[0], idx[1], idx[2]};
    i[d] += shift;
    return u[i[2]][i[1]][i[0]][c];
  };
  // Axis by axis over the whole ghosted plane: later axes overwrite edge and corner ghosts from
  // values the earlier axes made valid.
  for (int d = 0; d < 3; ++d) {
    if (grid.periodic(d)) continue;
    const PetscInt N = grid.n(d);
    for (int side = 0; side < 2; ++side) {
      if (side == 0 ? !grid.atLow(d) : !grid.atHigh(d)) continue;
      const int f = 2 * d + side;
      const Vec3 w = homogeneous ? Vec3{} : wallVelocity(bc, f);
      const bool slip = bc.type[f] == BcType::Slip;
      forPlane(g, d, [&](PetscInt* idx) {
        // Inside neighbours of the ghost layer: first and second cell from the wall.
        idx[d] = side == 0 ? 0 : N - 1;
        const PetscInt in = side == 0 ? 1 : -1;
        for (int c = 0; c < 3; ++c) {
          if (c == d) continue;
          PetscScalar u0 = at(idx, 0, d, c), u1 = at(idx, in, d, c);
          at(idx, -in, d, c) = slip ? u0 : (8.0 * w[c] - 6.0 * u0 + u1) / 3.0;
        }
        if (side == 0) {
          at(idx, 0, d, d) = w[d];
          at(idx, -1, d, d) = 2.0 * w[d] - at(idx, 1, d, d);
        } else {
          at(idx, 1, d, d) = w[d];  // face N, in the ghost layer
        }
      });
    }
  }
}

void fillCellGhosts(const Grid& grid, PetscScalar*** p)
{
  GhostBox g = ghostBox(grid.cellDM());
  for (int d = 0; d < 3; ++d) {
    if (grid.periodic(d)) continue;
    for (int side = 0; side < 2; ++side) {
      if (side == 0 ? !grid.atLow(d) : !grid.atHigh(d)) continue;
      forPlane(g, d, [&](PetscInt* idx) {
        PetscInt in[3] = {idx[0], idx[1], idx[2]}, out[3] = {idx[0], idx[1], idx[2]};
        in[d] = side == 0 ? 0 : grid.n(d) - 1;
        out[d] = side == 0 ? -1 : grid.n(d);
        p[out[2]][out[1]][out[0]] = p[in[2]][in[1]][in[0]];
      });
    }
  }
}

} // namespace vp
