#pragma once
// Ghost values at physical boundaries, the one place where boundary conditions enter the
// operators. Call after every DMGlobalToLocal of a face or cell field (periodic ghosts come
// from PETSc, wall ghosts from here).
//
// Face velocity (normal component c on a wall axis c): face 0 is owned and fixed to the wall's
// normal velocity, face N lives in the ghost layer and is set to it too.
// Tangential components, ghost cell half a cell outside the wall:
//   wall / velocity: quadratic extrapolation through the wall value, u_g = (8 u_w - 6 u_0 + u_1)/3,
//                    exact for parabolic profiles (plane Poiseuille is reproduced to round-off);
//   slip:            u_g = u_0 (zero normal derivative).
// Cell fields (pressure, Phi): zero normal derivative, p_g = p_0.
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"

namespace vp {

// Fills the boundary ghosts of a local face array (dof 3, from Grid::faceDM). With homogeneous =
// true all wall velocities are taken as zero (the boundary condition of a velocity increment).
void fillFaceGhosts(const Grid& grid, const BoundaryConfig& bc, PetscScalar**** u, bool homogeneous = false);

// Fills the boundary ghosts of a local cell array (dof 1, from Grid::cellDM): Neumann.
void fillCellGhosts(const Grid& grid, PetscScalar*** p);

// A face unknown whose value is fixed by the boundary condition (normal face on a wall).
inline bool isFixedFace(const Grid& grid, int c, PetscInt idx) { return !grid.periodic(c) && idx == 0; }

// Wall velocity vector of face f (zero unless the face is of type velocity).
inline Vec3 wallVelocity(const BoundaryConfig& bc, int f)
{
  return bc.type[f] == BcType::Velocity ? bc.velocity[f] : Vec3{};
}

} // namespace vp
