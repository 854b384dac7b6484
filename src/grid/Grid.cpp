#include "vp/grid/Grid.hpp"
#include "vp/core/Error.hpp"
#include <string>

namespace vp {

Grid::Grid(MPI_Comm comm, const GridConfig& g, const BoundaryConfig& bc) : comm_(comm)
{
  DMBoundaryType bt[3];
  for (int d = 0; d < 3; ++d) {
    n_[d] = g.n[d];
    lo_[d] = g.lo[d];
    hi_[d] = g.hi[d];
    h_[d] = g.spacing(d);
    periodic_[d] = bc.periodic(d);
    // Wall axes keep a ghost layer at the physical boundary, filled by Boundary::fill*.
    bt[d] = periodic_[d] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
  }

  // The partition may be too fine for the grid: report it as bad input, not a PETSc trace.
  PetscInt split[3];
  for (int d = 0; d < 3; ++d) split[d] = g.ranks[d] > 0 ? g.ranks[d] : PETSC_DECIDE;
  VP_CALL(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2],
                       split[0], split[1], split[2], 1, 1, nullptr, nullptr, nullptr, &cellDM_));
  VP_CALL(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  PetscErrorCode ierr = DMSetUp(cellDM_);
  VP_CALL(PetscPopErrorHandler());
  if (ierr) {
    int size;
    MPI_Comm_size(comm, &size);
    DMDestroy(&cellDM_);
    throw InputError("option -grid_n: " + std::to_string(n_[0]) + "," + std::to_string(n_[1]) + "," +
                     std::to_string(n_[2]) + " cells cannot be split over " + std::to_string(size) +
                     " ranks (each rank needs at least 1 cell per axis and periodic axes at least 2); "
                     "use more cells or fewer ranks");
  }
  PetscInt m, np, p;
  const PetscInt *lx, *ly, *lz;
  VP_CALL(DMDAGetInfo(cellDM_, nullptr, nullptr, nullptr, nullptr, &m, &np, &p, nullptr, nullptr,
                      nullptr, nullptr, nullptr, nullptr));
  VP_CALL(DMDAGetOwnershipRanges(cellDM_, &lx, &ly, &lz));
  exchanges_ = m * np * p > 1 || periodic_[0] || periodic_[1] || periodic_[2];
  // PETSc's STAR stencil leaves edge ghosts stale, which advection needs: BOX for the velocity.
  VP_CALL(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, n_[0], n_[1], n_[2], m, np, p, 3, 1,
                       lx, ly, lz, &faceDM_));
  VP_CALL(DMSetUp(faceDM_));
  // Matrices of the three decoupled velocity components: 7 entries per row, preallocated by
  // their owner (DMDA block fills need periodic sizes divisible by 3, the default 21 per row).
  VP_CALL(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2], m, np, p, 3, 1,
                       lx, ly, lz, &faceSolveDM_));
  VP_CALL(DMSetMatrixPreallocateSkip(faceSolveDM_, PETSC_TRUE));
  VP_CALL(DMSetUp(faceSolveDM_));
  VP_CALL(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2], m, np, p, 3, 0,
                       lx, ly, lz, &cellVectorDM_));
  VP_CALL(DMSetUp(cellVectorDM_));
  const char* names[3] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) VP_CALL(DMDASetFieldName(cellVectorDM_, c, names[c]));

  PetscInt xs[3], xm[3];
  VP_CALL(DMDAGetCorners(cellDM_, &xs[0], &xs[1], &xs[2], &xm[0], &xm[1], &xm[2]));
  for (int d = 0; d < 3; ++d) {
    start_[d] = xs[d];
    end_[d] = xs[d] + xm[d];
  }
}

Grid::~Grid()
{
  DMDestroy(&cellVectorDM_);
  DMDestroy(&faceSolveDM_);
  DMDestroy(&faceDM_);
  DMDestroy(&cellDM_);
}

} // namespace vp
