#include "vp/core/Error.hpp"
#include <sstream>

namespace vp {

PetscFailure::PetscFailure(PetscErrorCode c, const char* file, int line)
  : std::runtime_error("PETSc error " + std::to_string(c) + " at " + file + ":" + std::to_string(line)),
    code(c)
{
}

void failOption(const std::string& option, const std::string& what)
{
  throw InputError("option " + option + ": " + what);
}

void failOption(const std::string& option, const std::string& what, double value)
{
  failOption(option, what + ", got " + formatNumber(value));
}

std::string formatNumber(double v, int digits)
{
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

} // namespace vp
