#include "vp/grid/Grid.hpp"
#include "vp/core/Error.hpp"
#include <stdexcept>
#include <string>
#include <vector>

namespace vp {

Grid::Grid(MPI_Comm comm, const GridConfig& g, const BoundaryConfig& bc) : comm_(comm)
{
  for (int d = 0; d < 3; ++d) {
    n_[d] = g.n[d];
    lo_[d] = g.lo[d];
    hi_[d] = g.hi[d];
    h_[d] = g.spacing(d);
    periodic_[d] = bc.periodic(d);
  }
  // The partition may be too fine for the grid: report it as bad input, not a PETSc trace.
  PetscInt split[3];
  for (int d = 0; d < 3; ++d) split[d] = g.ranks[d] > 0 ? g.ranks[d] : PETSC_DECIDE;
  if (!createDMs(split, {nullptr, nullptr, nullptr})) {
    int size;
    MPI_Comm_size(comm, &size);
    throw InputError("option -grid_n: " + std::to_string(n_[0]) + "," + std::to_string(n_[1]) + "," +
                     std::to_string(n_[2]) + " cells cannot be split over " + std::to_string(size) +
                     " ranks (each rank needs at least 1 cell per axis and periodic axes at least 2); "
                     "use more cells or fewer ranks");
  }
}

Grid::Grid(const Grid& fine, const Coarsen&) : comm_(fine.comm_)
{
  PetscInt split[3];
  const PetscInt* lf[3];
  VP_CALL(DMDAGetInfo(fine.cellDM_, nullptr, nullptr, nullptr, nullptr, &split[0], &split[1], &split[2], nullptr,
                      nullptr, nullptr, nullptr, nullptr, nullptr));
  VP_CALL(DMDAGetOwnershipRanges(fine.cellDM_, &lf[0], &lf[1], &lf[2]));
  std::vector<PetscInt> lc[3];
  for (int d = 0; d < 3; ++d) {
    n_[d] = fine.n_[d] / 2;
    lo_[d] = fine.lo_[d];
    hi_[d] = fine.hi_[d];
    h_[d] = 2 * fine.h_[d];
    periodic_[d] = fine.periodic_[d];
    for (PetscInt r = 0; r < split[d]; ++r) lc[d].push_back(lf[d][r] / 2);
  }
  if (!createDMs(split, {lc[0].data(), lc[1].data(), lc[2].data()}))
    throw std::logic_error("Grid: a coarsenable grid could not be coarsened");
}

bool Grid::coarsenable(int minCells) const
{
  PetscInt split[3];
  const PetscInt* l[3];
  VP_CALL(DMDAGetInfo(cellDM_, nullptr, nullptr, nullptr, nullptr, &split[0], &split[1], &split[2], nullptr, nullptr,
                      nullptr, nullptr, nullptr, nullptr));
  VP_CALL(DMDAGetOwnershipRanges(cellDM_, &l[0], &l[1], &l[2]));
  for (int d = 0; d < 3; ++d) {
    if (n_[d] / 2 < minCells) return false;
    for (PetscInt r = 0; r < split[d]; ++r)
      if (l[d][r] % 2) return false;  // every rank's coarse cells are its own fine cells' parents
  }
  return true;
}

bool Grid::createDMs(const PetscInt split[3], std::array<const PetscInt*, 3> ranges)
{
  DMBoundaryType bt[3];
  // Wall axes keep a ghost layer at the physical boundary, filled by Boundary::fill*.
  for (int d = 0; d < 3; ++d) bt[d] = periodic_[d] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
  VP_CALL(DMDACreate3d(comm_, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2], split[0], split[1],
                       split[2], 1, 1, ranges[0], ranges[1], ranges[2], &cellDM_));
  PetscErrorCode ierr;
  {
    QuietPetscErrors quiet;  // a split PETSc cannot make is reported by the caller
    ierr = DMSetUp(cellDM_);
  }
  if (ierr) {
    DMDestroy(&cellDM_);
    return false;
  }
  PetscInt m, np, p;
  const PetscInt *lx, *ly, *lz;
  VP_CALL(DMDAGetInfo(cellDM_, nullptr, nullptr, nullptr, nullptr, &m, &np, &p, nullptr, nullptr,
                      nullptr, nullptr, nullptr, nullptr));
  VP_CALL(DMDAGetOwnershipRanges(cellDM_, &lx, &ly, &lz));
  exchanges_ = m * np * p > 1 || periodic_[0] || periodic_[1] || periodic_[2];
  // PETSc's STAR stencil leaves edge ghosts stale, which advection needs: BOX for the velocity.
  VP_CALL(DMDACreate3d(comm_, bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, n_[0], n_[1], n_[2], m, np, p, 3, 1,
                       lx, ly, lz, &faceDM_));
  VP_CALL(DMSetUp(faceDM_));
  // Matrices of the three decoupled velocity components: 7 entries per row, preallocated by
  // their owner (DMDA block fills need periodic sizes divisible by 3, the default 21 per row).
  VP_CALL(DMDACreate3d(comm_, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2], m, np, p, 3, 1,
                       lx, ly, lz, &faceSolveDM_));
  VP_CALL(DMSetMatrixPreallocateSkip(faceSolveDM_, PETSC_TRUE));
  VP_CALL(DMSetUp(faceSolveDM_));
  VP_CALL(DMDACreate3d(comm_, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, n_[0], n_[1], n_[2], m, np, p, 3, 0,
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
  return true;
}

Grid::~Grid()
{
  DMDestroy(&cellVectorDM_);
  DMDestroy(&faceSolveDM_);
  DMDestroy(&faceDM_);
  DMDestroy(&cellDM_);
}

} // namespace vp
