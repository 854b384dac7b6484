#pragma once
// Errors: InputError for bad user input (options, case and restart files), reported by vpsolve as
// one clear line and a non-zero exit; PetscFailure for an error code returned by PETSc.
#include <petscsys.h>
#include <stdexcept>
#include <string>

namespace vp {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run stopped by a failed health check (docs/robustness.md): raised on every rank alike, after a
// snapshot for inspection; vpsolve exits with status 3.
struct RunFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A time step that cannot be completed (a solver that did not converge, unstable lubrication,
// lost particles), decided collectively so that every rank raises it: the run stops like a failed
// health check. Anything else raised inside a step aborts the job.
struct StepFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PetscFailure : std::runtime_error {
  PetscFailure(PetscErrorCode code, const char* file, int line);
  PetscErrorCode code;
};

// While alive, a failing PETSc call returns its error code without PETSc's own trace: the caller
// reports the error in its own words (a file that cannot be written, say).
class QuietPetscErrors {
public:
  QuietPetscErrors() { PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); }
  ~QuietPetscErrors() { PetscPopErrorHandler(); }
  QuietPetscErrors(const QuietPetscErrors&) = delete;
  QuietPetscErrors& operator=(const QuietPetscErrors&) = delete;
};

// Throws InputError("option <option>: <what>").
[[noreturn]] void failOption(const std::string& option, const std::string& what);
// Throws InputError("option <option>: <what>, got <value>").
[[noreturn]] void failOption(const std::string& option, const std::string& what, double value);
// A number as the user would write it (6 significant digits for error messages; more for records).
std::string formatNumber(double v, int digits = 6);

} // namespace vp

// Call a PETSc function from C++ code that does not return PetscErrorCode: throw on failure.
#define VP_CALL(...)                                                     \
  do {                                                                   \
    PetscErrorCode vp_ierr_ = (__VA_ARGS__);                             \
    if (vp_ierr_ != 0) throw ::vp::PetscFailure(vp_ierr_, __FILE__, __LINE__); \
  } while (0)
