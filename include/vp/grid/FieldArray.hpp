#pragma once
// Scoped [k][j][i][c] (faces, dof 3) and [k][j][i] (cells) access to a DMDA vector with global
// indices, as DMDAVecGetArrayDOF / DMDAVecGetArray give, but with the pointer tables built once per
// vector and kept with it (PetscObjectCompose): PETSc allocates and fills them, a table the size of
// the ghosted grid, at every call - measured 0.3-0.5 ms per call at 64^3, several times per step.
#include <petscdmda.h>

namespace vp {

class FaceArray {
public:
  FaceArray(DM dm, Vec v, bool read = false);
  ~FaceArray();
  FaceArray(const FaceArray&) = delete;
  FaceArray& operator=(const FaceArray&) = delete;
  PetscScalar**** a;

private:
  Vec v_;
  bool read_;
  PetscScalar* base_;
};

class CellArray {
public:
  CellArray(DM dm, Vec v, bool read = false);
  ~CellArray();
  CellArray(const CellArray&) = delete;
  CellArray& operator=(const CellArray&) = delete;
  PetscScalar*** a;

private:
  Vec v_;
  bool read_;
  PetscScalar* base_;
};

} // namespace vp
