#pragma once
// Scoped [k][j][i][c] (faces, dof 3) and [k][j][i] (cells) access to a DMDA vector with global
// indices, as DMDAVecGetArrayDOF / DMDAVecGetArray give, but with the pointer tables built once per
// vector and kept with it (PetscObjectCompose): PETSc allocates and fills them, a table the size of
// the ghosted grid, at every call - measured 0.3-0.5 ms per call at 64^3, several times per step.
#include <petscdmda.h>

namespace vp {

// T: PetscScalar**** (faces, [k][j][i][c]) or PetscScalar*** (cells, [k][j][i]).
template <class T>
class DmdaArray {
public:
  DmdaArray(DM dm, Vec v, bool read = false);
  ~DmdaArray();
  DmdaArray(const DmdaArray&) = delete;
  DmdaArray& operator=(const DmdaArray&) = delete;
  T a;

private:
  void restore();
  Vec v_;
  bool read_;
  PetscScalar* base_;
};

using FaceArray = DmdaArray<PetscScalar****>;
using CellArray = DmdaArray<PetscScalar***>;

} // namespace vp
