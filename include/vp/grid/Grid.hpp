#pragma once
// The uniform 3-D grid and its domain decomposition. One decomposition for every field and for the
// particles: the cell-centred DMDA (pressure) decides it, the face DMDAs (velocity) copy its
// ownership ranges. Velocity face i-1/2 of cell i is stored at index i (see docs/fluid.md, grid).
#include "vp/core/Config.hpp"
#include <petscdmda.h>
#include <array>

namespace vp {

class Grid {
public:
  Grid(MPI_Comm comm, const GridConfig& grid, const BoundaryConfig& bc);
  // The grid of half the cells per axis over the same box and ranks, each rank's coarse cells the
  // parents of its fine ones (viscous multigrid); only where `fine.coarsenable()`.
  struct Coarsen {};
  Grid(const Grid& fine, const Coarsen&);
  ~Grid();
  Grid(const Grid&) = delete;
  Grid& operator=(const Grid&) = delete;

  MPI_Comm comm() const { return comm_; }
  DM cellDM() const { return cellDM_; }           // dof 1, STAR, width 1 (pressure, Phi)
  DM faceDM() const { return faceDM_; }           // dof 3, BOX, width 1 (velocity on faces)
  DM faceSolveDM() const { return faceSolveDM_; } // dof 3, STAR, for the velocity matrices
  DM cellVectorDM() const { return cellVectorDM_; } // dof 3, cell-centred vectors for output

  int n(int d) const { return n_[d]; }
  double lo(int d) const { return lo_[d]; }
  double hi(int d) const { return hi_[d]; }
  double h(int d) const { return h_[d]; }
  bool periodic(int d) const { return periodic_[d]; }
  double cellVolume() const { return h_[0] * h_[1] * h_[2]; }
  long cells() const { return static_cast<long>(n_[0]) * n_[1] * n_[2]; }

  // Owned cells [start, end) per axis, and whether this rank touches a physical (non-periodic)
  // boundary on the low/high side of an axis.
  PetscInt start(int d) const { return start_[d]; }
  PetscInt end(int d) const { return end_[d]; }
  bool atLow(int d) const { return !periodic_[d] && start_[d] == 0; }
  bool atHigh(int d) const { return !periodic_[d] && end_[d] == n_[d]; }
  // Whether a ghost update moves any value: not for one rank without periodic axes, where every
  // ghost lies outside the domain and is filled by the boundary rules (Boundary.hpp).
  bool exchangesGhosts() const { return exchanges_; }

  // Whether every axis keeps at least minCells cells when halved and every rank's cell range per
  // axis is even (the coarse decomposition is the fine one halved).
  bool coarsenable(int minCells) const;

  double cellCentre(int d, PetscInt i) const { return lo_[d] + (i + 0.5) * h_[d]; }
  double faceCoord(int d, PetscInt i) const { return lo_[d] + i * h_[d]; }

private:
  // The four DMDAs on n_ with the given split (and ownership ranges, or PETSc's); false if PETSc
  // cannot split the grid so.
  bool createDMs(const PetscInt split[3], std::array<const PetscInt*, 3> ranges);

  MPI_Comm comm_;
  DM cellDM_ = nullptr, faceDM_ = nullptr, faceSolveDM_ = nullptr, cellVectorDM_ = nullptr;
  int n_[3];
  double lo_[3], hi_[3], h_[3];
  bool periodic_[3];
  bool exchanges_ = true;
  PetscInt start_[3], end_[3];
};

} // namespace vp
