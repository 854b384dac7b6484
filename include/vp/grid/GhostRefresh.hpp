#pragma once
// Refreshes the ghost layers of a DMDA local (ghosted) vector in place from the owned values of the
// same vector on the neighbouring ranks (and across periodic boundaries): a star forest whose
// leaves are the ghost points only. PETSc's DMLocalToLocal moves every local point, i.e. copies
// the whole vector per call (measured: as dear as a VecCopy); a solver whose iterate lives in the
// ghosted layout (the fused viscous CG) needs only the ghosts. Ghosts outside the domain (walls) are
// not touched: the boundary rules fill them (Boundary.hpp).
#include <petscdmda.h>
#include <petscsf.h>

namespace vp {

class GhostRefresh {
public:
  explicit GhostRefresh(DM da);
  ~GhostRefresh();
  GhostRefresh(const GhostRefresh&) = delete;
  GhostRefresh& operator=(const GhostRefresh&) = delete;

  // local: a local vector of `da` whose owned values are set; its in-domain ghosts are overwritten.
  void apply(Vec local) const;
  PetscInt ghostCount() const { return ghosts_; }

private:
  PetscSF sf_ = nullptr;
  PetscInt ghosts_ = 0;
};

} // namespace vp
