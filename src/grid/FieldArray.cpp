#include "vp/grid/FieldArray.hpp"
#include "vp/core/Error.hpp"
#include <vector>

namespace vp {

namespace {

// The pointer tables of one vector: valid while its array stays where it was.
struct Table {
  Vec owner = nullptr;  // VecDuplicate copies composed objects: a duplicate must not share this
  const PetscScalar* base = nullptr;
  PetscInt s[3] = {0, 0, 0}, m[3] = {0, 0, 0}, dof = 0;
  // Faces: a point's 3 values per (k, j, i), its row per (k, j), its plane per k.
  // Cells: a row per (k, j), its plane per k.
  std::vector<PetscScalar*> points;
  std::vector<PetscScalar**> lines;
  std::vector<PetscScalar***> slabs;
  void* array = nullptr;  // the outermost table, offset for global indices
};

PetscErrorCode destroyTable(void* t)
{
  delete static_cast<Table*>(t);
  return 0;
}

// Owned or ghosted box of v, by its length (as DMDAVecGetArray decides).
void box(DM dm, Vec v, PetscInt s[3], PetscInt m[3], PetscInt& dof)
{
  PetscInt n;
  VP_CALL(DMDAGetInfo(dm, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, &dof, nullptr, nullptr, nullptr,
                      nullptr, nullptr));
  VP_CALL(VecGetLocalSize(v, &n));
  VP_CALL(DMDAGetCorners(dm, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  if (n != m[0] * m[1] * m[2] * dof) VP_CALL(DMDAGetGhostCorners(dm, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
}

Table& table(DM dm, Vec v, PetscScalar* base)
{
  PetscContainer c;
  VP_CALL(PetscObjectQuery((PetscObject)v, "vp_array_table", (PetscObject*)&c));
  Table* t = nullptr;
  if (c) VP_CALL(PetscContainerGetPointer(c, (void**)&t));
  if (t && t->owner != v) t = nullptr;  // inherited from the vector this one duplicates
  PetscInt s[3], m[3], dof;
  box(dm, v, s, m, dof);
  const bool same = t && t->base == base && t->dof == dof && s[0] == t->s[0] && s[1] == t->s[1] && s[2] == t->s[2] &&
                    m[0] == t->m[0] && m[1] == t->m[1] && m[2] == t->m[2];
  if (same) return *t;
  if (!t) {
    t = new Table;
    VP_CALL(PetscContainerCreate(PETSC_COMM_SELF, &c));
    VP_CALL(PetscContainerSetPointer(c, t));
    VP_CALL(PetscContainerSetUserDestroy(c, destroyTable));
    VP_CALL(PetscObjectCompose((PetscObject)v, "vp_array_table", (PetscObject)c));
    VP_CALL(PetscContainerDestroy(&c));  // the vector holds it now
  }
  t->owner = v;
  t->base = base;
  t->dof = dof;
  for (int d = 0; d < 3; ++d) t->s[d] = s[d], t->m[d] = m[d];
  // Offsets so that global indices address the local array (what PETSc's tables do as well).
  const PetscInt nx = m[0], ny = m[1], nz = m[2];
  if (dof == 1) {
    t->points.resize(nz * ny);
    t->lines.resize(nz);
    for (PetscInt q = 0; q < nz * ny; ++q) t->points[q] = base + q * nx - s[0];
    for (PetscInt k = 0; k < nz; ++k) t->lines[k] = &t->points[k * ny] - s[1];
    t->array = &t->lines[0] - s[2];
  } else {
    t->points.resize(nz * ny * nx);
    t->lines.resize(nz * ny);
    t->slabs.resize(nz);
    for (PetscInt q = 0; q < nz * ny * nx; ++q) t->points[q] = base + q * dof;
    for (PetscInt q = 0; q < nz * ny; ++q) t->lines[q] = &t->points[q * nx] - s[0];
    for (PetscInt k = 0; k < nz; ++k) t->slabs[k] = &t->lines[k * ny] - s[1];
    t->array = &t->slabs[0] - s[2];
  }
  return *t;
}

} // namespace

template <class T>
DmdaArray<T>::DmdaArray(DM dm, Vec v, bool read) : v_(v), read_(read)
{
  if (read) VP_CALL(VecGetArrayRead(v, const_cast<const PetscScalar**>(&base_)));
  else VP_CALL(VecGetArray(v, &base_));
  try {
    a = static_cast<T>(table(dm, v, base_).array);
  } catch (...) {
    restore();
    throw;
  }
}

template <class T>
DmdaArray<T>::~DmdaArray()
{
  restore();
}

template <class T>
void DmdaArray<T>::restore()
{
  if (read_) VecRestoreArrayRead(v_, const_cast<const PetscScalar**>(&base_));
  else VecRestoreArray(v_, &base_);
}

template class DmdaArray<PetscScalar****>;
template class DmdaArray<PetscScalar***>;

} // namespace vp
