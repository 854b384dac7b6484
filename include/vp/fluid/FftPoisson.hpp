#pragma once
// The PETSc preconditioner type "fft": an exact inverse of the cell-centred 7-point operator
// A = -sum_d w_d D_d^2 on a uniform 3-D DMDA (dof 1), with homogeneous Neumann conditions on wall
// axes and periodic axes, by real-to-real transforms (FFTW-MPI): a DCT-II per wall axis and a
// discrete Hartley transform per periodic axis diagonalise A exactly, with eigenvalues
// sum_d w_d (2 - 2 cos theta_d), theta = pi k / N (wall) or 2 pi k / N (periodic). The zero mode
// (the constant null space) is set to zero, so the result has zero mean. With a wall z axis only
// the x-y planes are transformed and each (x, y) mode's z line is solved as the tridiagonal system
// it is (exact as well, and cheaper than a strided third transform). FFTW splits the z axis into
// slabs (one rank needs at least one z cell); the DMDA blocks reach the slabs through one
// VecScatter each way. Use -pressure_ksp_type preonly for a direct solve, or CG with it.
// Options (prefix of the PC): -pc_fft_plan estimate|measure (FFTW planning effort).
#include <petscpc.h>

namespace vp {

// Registers "fft" with PCRegister (idempotent; call after PetscInitialize).
void registerFftPreconditioner();

// The operator's weight per axis, w_d (A = -sum_d w_d D_d^2, D_d^2 the unit second difference):
// must be given before the PC is set up.
PetscErrorCode PCFftSetWeights(PC pc, const double w[3]);

} // namespace vp
