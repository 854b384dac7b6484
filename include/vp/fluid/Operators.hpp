#pragma once
// Discrete operators of the MAC scheme as pure functions on DMDA arrays. Inputs are local
// (ghosted, boundary ghosts filled) arrays; outputs are written at the owned entries only, in
// global index space. Face unknowns fixed by a wall (isFixedFace) are not written (but see
// advectionAndLaplacian).
#include "vp/core/Vec3.hpp"
#include "vp/grid/Grid.hpp"

namespace vp::ops {

// Convection in divergence form, N_c = sum_d d(u_d u_c)/dx_d, and the Laplacian L_c = lap u_c,
// at every owned, free face (one sweep: both need the same neighbours); unlike the other operators
// it writes N = L = 0 on the fixed faces, and N and L must be global (owned-box) arrays.
void advectionAndLaplacian(const Grid& grid, PetscScalar**** u, PetscScalar**** N, PetscScalar**** L);

// div u at every owned cell.
void divergence(const Grid& grid, PetscScalar**** u, PetscScalar*** div);

// out_c += scale * weight_c * d(phi)/dx_c at every owned, free face (phi local, ghosts filled;
// weight: a face field, 1 when null).
void addGradient(const Grid& grid, PetscScalar*** phi, double scale, PetscScalar**** out,
                 PetscScalar**** weight = nullptr);

// Velocity at cell centres (average of the two faces of each cell) for output.
void faceToCentre(const Grid& grid, PetscScalar**** u, PetscScalar**** centre);

struct FieldStats {
  double maxDivergence = 0;  // max |div u| over cells (1/s)
  double kineticEnergy = 0;  // sum over faces 0.5 u_c^2 dV (per unit density, m^5/s^2)
  double maxRate = 0;        // max_c max |u_c| / h_c (1/s), the CFL rate
  Vec3 meanVelocity;         // volume average of u over the domain (m/s): the superficial velocity
};
// Global statistics of a local face array (collective).
FieldStats stats(const Grid& grid, PetscScalar**** u);

} // namespace vp::ops
