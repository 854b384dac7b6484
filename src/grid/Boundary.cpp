#include "vp/grid/Boundary.hpp"
#include "vp/core/Error.hpp"

namespace vp {

namespace {

// The ghosted box of a local array in flat form: index ranges and the stride of each axis.
struct GhostBox {
  PetscInt s[3], e[3];  // ghosted index range [s, e) per axis
  PetscInt stride[3];   // values between neighbours along each axis
  // Offset of (i, j, k) from the first ghosted value.
  PetscInt at(PetscInt i, PetscInt j, PetscInt k) const
  {
    return (i - s[0]) * stride[0] + (j - s[1]) * stride[1] + (k - s[2]) * stride[2];
  }
};

GhostBox ghostBox(DM dm, PetscInt dof)
{
  GhostBox b;
  PetscInt m[3];
  VP_CALL(DMDAGetGhostCorners(dm, &b.s[0], &b.s[1], &b.s[2], &m[0], &m[1], &m[2]));
  for (int d = 0; d < 3; ++d) b.e[d] = b.s[d] + m[d];
  b.stride[0] = dof;
  b.stride[1] = dof * m[0];
  b.stride[2] = dof * m[0] * m[1];
  return b;
}

// Visits the offsets of every ghosted position of the plane idx[d] = layer, the lower axis
// innermost so that consecutive visits stay close in memory. Flat offsets, not the DMDA pointer
// tables: this runs in every product of the viscous operator.
template <class F>
void forPlane(const GhostBox& g, int d, PetscInt layer, F&& f)
{
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  PetscInt idx[3];
  idx[d] = layer;
  idx[a] = g.s[a];
  for (idx[b] = g.s[b]; idx[b] < g.e[b]; ++idx[b]) {
    PetscInt o = g.at(idx[0], idx[1], idx[2]);
    for (PetscInt n = g.s[a]; n < g.e[a]; ++n, o += g.stride[a]) f(o);
  }
}

} // namespace

void fillFaceGhosts(const Grid& grid, const BoundaryConfig& bc, PetscScalar**** u, bool homogeneous)
{
  const GhostBox g = ghostBox(grid.faceDM(), 3);
  PetscScalar* base = &u[g.s[2]][g.s[1]][g.s[0]][0];
  // Axis by axis over the whole ghosted plane: later axes overwrite edge and corner ghosts from
  // values the earlier axes made valid.
  for (int d = 0; d < 3; ++d) {
    if (grid.periodic(d)) continue;
    const PetscInt N = grid.n(d), sd = g.stride[d];
    for (int side = 0; side < 2; ++side) {
      if (side == 0 ? !grid.atLow(d) : !grid.atHigh(d)) continue;
      const int f = 2 * d + side;
      const Vec3 w = homogeneous ? Vec3{} : wallVelocity(bc, f);
      const bool slip = bc.type[f] == BcType::Slip;
      // The first cell from the wall; `in` steps to the second, -in to the ghost.
      const PetscInt in = side == 0 ? sd : -sd;
      forPlane(g, d, side == 0 ? 0 : N - 1, [&](PetscInt o) {
        PetscScalar* v = base + o;
        for (int c = 0; c < 3; ++c) {
          if (c == d) continue;
          v[c - in] = slip ? v[c] : (8.0 * w[c] - 6.0 * v[c] + v[c + in]) / 3.0;
        }
        if (side == 0) {
          v[d] = w[d];
          v[d - sd] = 2.0 * w[d] - v[d + sd];
        } else {
          v[d + sd] = w[d];  // face N, in the ghost layer
        }
      });
    }
  }
}

void fillCellGhosts(const Grid& grid, PetscScalar*** p)
{
  const GhostBox g = ghostBox(grid.cellDM(), 1);
  PetscScalar* base = &p[g.s[2]][g.s[1]][g.s[0]];
  for (int d = 0; d < 3; ++d) {
    if (grid.periodic(d)) continue;
    for (int side = 0; side < 2; ++side) {
      if (side == 0 ? !grid.atLow(d) : !grid.atHigh(d)) continue;
      const PetscInt out = side == 0 ? -g.stride[d] : g.stride[d];
      forPlane(g, d, side == 0 ? 0 : grid.n(d) - 1, [&](PetscInt o) { base[o + out] = base[o]; });
    }
  }
}

} // namespace vp
