#include "vp/grid/GhostRefresh.hpp"
#include "vp/core/Error.hpp"
#include <vector>

namespace vp {

GhostRefresh::GhostRefresh(DM da)
{
  PetscInt dof, xs, ys, zs, xm, ym, zm, gxs, gys, gzs, gxm, gym, gzm;
  VP_CALL(DMDAGetInfo(da, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, &dof, nullptr, nullptr,
                      nullptr, nullptr, nullptr));
  VP_CALL(DMDAGetCorners(da, &xs, &ys, &zs, &xm, &ym, &zm));
  VP_CALL(DMDAGetGhostCorners(da, &gxs, &gys, &gzs, &gxm, &gym, &gzm));
  ISLocalToGlobalMapping ltog;
  VP_CALL(DMGetLocalToGlobalMapping(da, &ltog));
  const PetscInt* global;  // global (PETSc-ordered) index of every local point; < 0 outside the domain
  VP_CALL(ISLocalToGlobalMappingGetIndices(ltog, &global));
  Vec gv;
  VP_CALL(DMGetGlobalVector(da, &gv));
  PetscLayout layout;
  VP_CALL(VecGetLayout(gv, &layout));
  PetscInt rstart, rend;
  VP_CALL(VecGetOwnershipRange(gv, &rstart, &rend));
  auto localIndex = [&](PetscInt i, PetscInt j, PetscInt k) { return (((k - gzs) * gym + (j - gys)) * gxm + (i - gxs)) * dof; };
  auto owned = [&](PetscInt i, PetscInt j, PetscInt k) {
    return i >= xs && i < xs + xm && j >= ys && j < ys + ym && k >= zs && k < zs + zm;
  };
  // Where each owned value sits in this rank's local array (indexed by global index - rstart).
  std::vector<PetscInt> ownedAt(rend - rstart);
  // The ghost points: their local index and the global index of the value they mirror.
  std::vector<PetscInt> leaves, roots;
  for (PetscInt k = gzs; k < gzs + gzm; ++k)
    for (PetscInt j = gys; j < gys + gym; ++j)
      for (PetscInt i = gxs; i < gxs + gxm; ++i)
        for (PetscInt c = 0; c < dof; ++c) {
          const PetscInt l = localIndex(i, j, k) + c;
          if (owned(i, j, k)) {
            ownedAt[global[l] - rstart] = l;
          } else if (global[l] >= 0) {
            leaves.push_back(l);
            roots.push_back(global[l]);
          }
        }
  VP_CALL(ISLocalToGlobalMappingRestoreIndices(ltog, &global));
  ghosts_ = static_cast<PetscInt>(leaves.size());
  // First: each ghost learns the local index of its value on the owning rank.
  PetscSF byGlobal;
  VP_CALL(PetscSFCreate(PetscObjectComm((PetscObject)da), &byGlobal));
  VP_CALL(PetscSFSetGraphLayout(byGlobal, layout, ghosts_, leaves.data(), PETSC_COPY_VALUES, roots.data()));
  std::vector<PetscInt> remoteAt(gxm * gym * gzm * dof, -1);
  VP_CALL(PetscSFBcastBegin(byGlobal, MPIU_INT, ownedAt.data(), remoteAt.data(), MPI_REPLACE));
  VP_CALL(PetscSFBcastEnd(byGlobal, MPIU_INT, ownedAt.data(), remoteAt.data(), MPI_REPLACE));
  // Then the forest used at every refresh: roots are positions in the owners' local arrays.
  std::vector<PetscSFNode> remote(ghosts_);
  for (PetscInt g = 0; g < ghosts_; ++g) {
    PetscMPIInt owner;
    VP_CALL(PetscLayoutFindOwner(layout, roots[g], &owner));
    remote[g].rank = owner;
    remote[g].index = remoteAt[leaves[g]];
  }
  VP_CALL(PetscSFDestroy(&byGlobal));
  VP_CALL(DMRestoreGlobalVector(da, &gv));
  VP_CALL(PetscSFCreate(PetscObjectComm((PetscObject)da), &sf_));
  VP_CALL(PetscSFSetGraph(sf_, gxm * gym * gzm * dof, ghosts_, leaves.data(), PETSC_COPY_VALUES, remote.data(),
                          PETSC_COPY_VALUES));
  VP_CALL(PetscSFSetUp(sf_));
}

GhostRefresh::~GhostRefresh() { PetscSFDestroy(&sf_); }

void GhostRefresh::apply(Vec local) const
{
  PetscScalar* a;
  VP_CALL(VecGetArray(local, &a));
  // Roots (owned points) and leaves (ghost points) are disjoint entries of the same array.
  VP_CALL(PetscSFBcastBegin(sf_, MPIU_SCALAR, a, a, MPI_REPLACE));
  VP_CALL(PetscSFBcastEnd(sf_, MPIU_SCALAR, a, a, MPI_REPLACE));
  VP_CALL(VecRestoreArray(local, &a));
}

} // namespace vp
