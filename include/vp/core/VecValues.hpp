#pragma once
// A vector's local values for the length of a scope: VecGetArrayRead / VecRestoreArrayRead if
// Read, else VecGetArray / VecRestoreArray. Converts to the array pointer. Not for PETSc callbacks
// (a failure throws, see Error.hpp).
#include "vp/core/Error.hpp"
#include <petscvec.h>
#include <type_traits>

namespace vp {

template <bool Read>
class Values {
  using Pointer = std::conditional_t<Read, const PetscScalar*, PetscScalar*>;

public:
  explicit Values(Vec v) : v_(v)
  {
    if constexpr (Read)
      VP_CALL(VecGetArrayRead(v, &a_));
    else
      VP_CALL(VecGetArray(v, &a_));
  }
  ~Values()
  {
    if constexpr (Read)
      VecRestoreArrayRead(v_, &a_);
    else
      VecRestoreArray(v_, &a_);
  }
  Values(const Values&) = delete;
  Values& operator=(const Values&) = delete;
  operator Pointer() const { return a_; }

private:
  Vec v_;
  Pointer a_;
};
using ReadValues = Values<true>;
using WriteValues = Values<false>;

} // namespace vp
