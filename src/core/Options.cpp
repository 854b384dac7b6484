#include "vp/core/Options.hpp"
#include "vp/core/Error.hpp"
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <petscsys.h>

namespace vp {

namespace {

std::vector<OptionInfo> registry;
bool helpMode = false;

// A number as the record keeps it: every digit, so that equal values compare equal as text.
std::string canonical(double v)
{
  char b[32];
  for (int digits = 15; digits <= 17; ++digits) {  // the shortest form that reads back the same
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

std::string joinNumbers(const double* v, std::size_t n)
{
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += (i ? "," : "") + canonical(v[i]);
  return s;
}

// A bad value: thrown, or in help mode noted in the listing.
struct BadValue {
  std::string message;
};

double parseReal(const std::string& text)
{
  if (text.empty()) throw BadValue{"needs a number"};
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != 0) throw BadValue{"'" + text + "' is not a number"};
  if (!std::isfinite(v)) throw BadValue{"'" + text + "' is not a finite number"};
  return v;
}

int parseInt(const std::string& text)
{
  if (text.empty()) throw BadValue{"needs an integer"};
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (*end == 0 && end != text.c_str()) {
    if (errno == ERANGE || v < INT_MIN || v > INT_MAX) throw BadValue{"'" + text + "' is out of the integer range"};
    return static_cast<int>(v);
  }
  // 1e3 is an integer written as a real: accept it when it is one exactly.
  double d;
  try {
    d = parseReal(text);
  } catch (const BadValue&) {
    throw BadValue{"'" + text + "' is not an integer"};
  }
  if (d != std::floor(d)) throw BadValue{"'" + text + "' is not an integer"};
  if (d < INT_MIN || d > INT_MAX) throw BadValue{"'" + text + "' is out of the integer range"};
  return static_cast<int>(d);
}

std::vector<double> parseAnyList(const std::string& text)
{
  std::vector<double> v;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    v.push_back(parseReal(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return v;
    start = comma + 1;
  }
}

std::vector<double> parseList(const std::string& text, std::size_t n, const char* form)
{
  const std::vector<double> v = parseAnyList(text);
  if (v.size() != n)
    throw BadValue{"needs " + std::to_string(n) + " comma-separated values (" + form + "), got " + std::to_string(v.size())};
  return v;
}

OptionInfo* find(const std::string& name)
{
  for (auto& o : registry)
    if (o.name == name) return &o;
  return nullptr;
}

// Parses with f; a bad value throws InputError naming the option (or, in help mode, is noted).
template <class T, class F>
T parsed(const char* name, const char* raw, T def, F f)
{
  if (!raw) return def;
  try {
    return f(std::string(raw));
  } catch (const BadValue& e) {
    if (!helpMode) failOption(name, e.message);
    find(name)->value = "(bad value: " + e.message + ")";
    return def;
  }
}

std::size_t editDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// PETSc options that PETSc itself reads at solve time, at a solver's first set-up or at exit.
bool readLaterByPetsc(const std::string& name)
{
  const bool solver = name.rfind("pressure_", 0) == 0 || name.rfind("velocity_", 0) == 0;
  if (solver)
    for (const char* part : {"sub_", "mg_levels_", "mg_coarse_", "redundant_"})
      if (name.find(part) != std::string::npos) return true;
  static const char* const prefixes[] = {"log", "options_", "malloc", "info", "objects_", "fp_trap", "on_error",
                                         "no_signal_handler", "debugger", "start_in_debugger", "stop_for_debugger",
                                         "memory_view", "checkstack", "history", "help", "version", "viewer_"};
  for (const char* p : prefixes)
    if (name.rfind(p, 0) == 0) return true;
  for (const char* part : {"_view", "monitor", "converged_reason"})
    if (name.find(part) != std::string::npos) return true;
  return false;
}

} // namespace

const char* OptionGroup::raw(const char* name, const std::string& defaultText, const char* help)
{
  OptionInfo* o = find(name);
  if (!o) {
    registry.push_back({title_, name, help, defaultText, defaultText, false, setup_});
    o = &registry.back();
  }
  char buf[16384];
  PetscBool set = PETSC_FALSE;
  VP_CALL(PetscOptionsGetString(nullptr, nullptr, name, buf, sizeof buf, &set));
  if (!set) return nullptr;
  if (std::strlen(buf) >= sizeof buf - 1) failOption(name, "value longer than " + std::to_string(sizeof buf - 2) + " characters");
  o->given = true;
  o->value = buf;
  buffer_ = buf;
  return buffer_.c_str();
}

void OptionGroup::setValue(const char* name, const std::string& value) { find(name)->value = value; }

double OptionGroup::real(const char* name, double def, const char* help)
{
  const char* r = raw(name, canonical(def), help);
  const double v = parsed(name, r, def, parseReal);
  if (r && !helpMode) setValue(name, canonical(v));
  return v;
}

int OptionGroup::integer(const char* name, int def, const char* help)
{
  const char* r = raw(name, std::to_string(def), help);
  const int v = parsed(name, r, def, parseInt);
  if (r && !helpMode) setValue(name, std::to_string(v));
  return v;
}

bool OptionGroup::flag(const char* name, bool def, const char* help)
{
  const char* r = raw(name, def ? "true" : "false", help);
  const bool v = parsed(name, r, def, [](const std::string& t) {
    std::string s = t;
    std::transform(s.begin(), s.end(), s.begin(), ::tolower);
    if (s.empty() || s == "1" || s == "true" || s == "yes" || s == "on") return true;
    if (s == "0" || s == "false" || s == "no" || s == "off") return false;
    throw BadValue{"'" + t + "' is not a boolean (true, false, 1, 0, yes, no)"};
  });
  if (r) setValue(name, v ? "true" : "false");
  return v;
}

std::string OptionGroup::text(const char* name, const std::string& def, const char* help)
{
  const char* r = raw(name, def, help);
  return r ? std::string(r) : def;
}

int OptionGroup::choice(const char* name, const std::vector<std::string>& values, int def, const char* help)
{
  std::string text = std::string(help) + " (";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + values[i];
  const char* r = raw(name, values[def], (text + ")").c_str());
  return parsed(name, r, def, [&](const std::string& t) {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (t == values[i]) return static_cast<int>(i);
    std::string valid;
    for (std::size_t i = 0; i < values.size(); ++i) valid += (i ? ", " : "") + values[i];
    throw BadValue{"unknown value '" + t + "' (valid: " + valid + ")"};
  });
}

Vec3 OptionGroup::vec3(const char* name, const Vec3& def, const char* help, bool* given)
{
  const double d[3] = {def.x, def.y, def.z};
  const char* r = raw(name, joinNumbers(d, 3), help);
  if (given) *given = r != nullptr;
  const Vec3 v = parsed(name, r, def, [](const std::string& t) {
    const std::vector<double> v = parseList(t, 3, "x,y,z");
    return Vec3{v[0], v[1], v[2]};
  });
  const double vv[3] = {v.x, v.y, v.z};
  if (r && !helpMode) setValue(name, joinNumbers(vv, 3));
  return v;
}

std::vector<double> OptionGroup::reals(const char* name, std::size_t n, const char* form, const char* help)
{
  const char* r = raw(name, std::string("none (") + form + ")", help);
  const std::vector<double> v = parsed(name, r, std::vector<double>{}, [&](const std::string& t) { return parseList(t, n, form); });
  if (r && !helpMode) setValue(name, joinNumbers(v.data(), v.size()));
  return v;
}

std::vector<double> OptionGroup::realList(const char* name, const char* help)
{
  const char* r = raw(name, "none", help);
  const std::vector<double> v = parsed(name, r, std::vector<double>{}, parseAnyList);
  if (r && !helpMode) setValue(name, joinNumbers(v.data(), v.size()));
  return v;
}

const std::vector<OptionInfo>& registeredOptions() { return registry; }

void setOptionsHelpMode(bool on) { helpMode = on; }

bool optionsHelpMode() { return helpMode; }

std::vector<std::string> unusedOptions()
{
  PetscInt n;
  char** names;
  char** values;
  VP_CALL(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::vector<std::string> out;
  for (PetscInt i = 0; i < n; ++i) {
    const std::string name = std::string("-") + names[i];
    // A name close to one of vpsolve's is a misspelling even if it looks like a PETSc viewer's.
    const bool solver = name.rfind("-pressure_", 0) == 0 || name.rfind("-velocity_", 0) == 0;
    if (!readLaterByPetsc(names[i]) || (!solver && !nearestOption(name).empty())) out.push_back(name);
  }
  VP_CALL(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  return out;
}

std::string nearestOption(const std::string& name)
{
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(3, name.size() / 3) + 1;
  for (const auto& o : registry) {
    const std::size_t d = editDistance(name, o.name);
    if (d < bestDistance) {
      bestDistance = d;
      best = o.name;
    }
  }
  return best;
}

void printOptionHelp(int rank)
{
  if (rank != 0) return;
  std::vector<std::string> groups;
  for (const auto& o : registry)
    if (std::find(groups.begin(), groups.end(), o.group) == groups.end()) groups.push_back(o.group);
  for (const auto& g : groups) {
    std::printf("\n%s\n", g.c_str());
    for (const auto& o : registry) {
      if (o.group != g) continue;
      std::string head = "  " + o.name + " <" + o.defaultText + ">";
      if (o.given) head += " (given: " + o.value + ")";
      std::printf("%-44s %s\n", head.c_str(), o.help.c_str());
    }
  }
  std::fflush(stdout);
}

std::string setupOptionsText()
{
  std::string s;
  for (const auto& o : registry)
    if (o.setup) s += o.name + " " + o.value + "\n";
  return s;
}

} // namespace vp
