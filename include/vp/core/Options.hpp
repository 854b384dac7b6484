#pragma once
// The one options layer of vpsolve. Every option is read through an OptionGroup, which takes the
// raw text from PETSc's options database and parses it itself, so that a bad value is reported as
// "option -name: ..." (type, vector length, finiteness) instead of a PETSc trace. Each read option
// is recorded (group, default, help, effective value): -help prints the record, the run record
// (run.json) writes it, and a misspelt option is matched against it. Ranges and consistency are
// checked by the configurations' validate() functions, not here.
#include "vp/core/Vec3.hpp"
#include <string>
#include <vector>

namespace vp {

struct OptionInfo {
  std::string group, name, help;
  std::string defaultText;  // as -help shows it, vectors in full
  std::string value;        // effective value (the default when not given)
  bool given = false;
  bool setup = true;        // defines the physical set-up (compared on restart)
};

class OptionGroup {
public:
  // setup: the group's options define the physical set-up (a restart must not change them);
  // false for run control (time span, output, solvers, checks).
  explicit OptionGroup(std::string title, bool setup = true) : title_(std::move(title)), setup_(setup) {}

  double real(const char* name, double def, const char* help);
  int integer(const char* name, int def, const char* help);
  bool flag(const char* name, bool def, const char* help);
  std::string text(const char* name, const std::string& def, const char* help);
  // One of `values`; returns its index (def: the default's index).
  int choice(const char* name, const std::vector<std::string>& values, int def, const char* help);
  Vec3 vec3(const char* name, const Vec3& def, const char* help, bool* given = nullptr);
  // Exactly `n` comma-separated numbers when given (`form` names them for messages), else empty.
  std::vector<double> reals(const char* name, std::size_t n, const char* form, const char* help);
  // Any number of comma-separated numbers (empty when not given).
  std::vector<double> realList(const char* name, const char* help);

private:
  // The raw text of an option (nullptr if not given), recorded with its default.
  const char* raw(const char* name, const std::string& defaultText, const char* help);
  void setValue(const char* name, const std::string& value);
  std::string title_;
  bool setup_;
  std::string buffer_;
};

// Every option read so far, in reading order.
const std::vector<OptionInfo>& registeredOptions();
// In help mode a value that does not parse is reported by -help's listing instead of thrown, so
// that every group is read and listed.
void setOptionsHelpMode(bool on);
// Readers skip the checks they make themselves in help mode.
bool optionsHelpMode();

// Options in the database that nothing has read, except the PETSc options that are read later
// (viewers, monitors, logging, debugging): the misspelt ones.
std::vector<std::string> unusedOptions();
// The registered option nearest to a misspelt name (edit distance), or "" if none is close.
std::string nearestOption(const std::string& name);

// Prints the registered options grouped, with defaults (rank 0 only).
void printOptionHelp(int rank);
// "-name value" lines of the set-up options, in registration order (compared on restart).
std::string setupOptionsText();

} // namespace vp
