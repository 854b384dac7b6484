#include "vp/particles/ParticleCheckpoint.hpp"
#include "vp/particles/ContactHandOff.hpp"
#include <algorithm>
#include <map>

namespace vp {

namespace {

// One row per particle: the kCheckpoint fields of ParticleFields.hpp, each as doubles.
template <class F>
void forCheckpointFields(F&& f)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo& info, auto sync) {
    if constexpr ((decltype(sync)::value & kCheckpoint) != 0) f(value, info.columns);
  });
}

std::string particleColumns()
{
  std::string s;
  forCheckpointFields([&](auto, const char* cols) { s += (s.empty() ? "" : ",") + std::string(cols); });
  return s;
}

int particleColumnCount()
{
  double row[256], *o = row;
  ParticleRecord r;
  forCheckpointFields([&](auto value, const char*) { writeDoubles(r.*value, o); });
  return static_cast<int>(o - row);
}

const std::string kParticleColumns = particleColumns();
const int kParticleCols = particleColumnCount();
const char* const kColumnsText = "particle_columns";
const char* const kParticles = "particles";
const char* const kContacts = "contacts";
constexpr int kContactCols = 6;  // id, partner id, spring x, y, z, departure state (absent from the oldest files)
// id, the Basset modes' x, y, z by mode, the velocity change of a contact under way (absent in the
// dataset's first form: none); rows only for particles in a window (the dataset is absent from the
// oldest files: none were).
constexpr int kWindowCols = 4 + 3 * kBassetModes;
const char* const kWindows = "window_history";

std::vector<std::string> split(const std::string& text)
{
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    out.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// The particle rows of a checkpoint (named by fileColumns) in this build's layout. Returns an
// error, or "".
std::string toCurrentLayout(const std::string& fileColumns, int fileCols, std::vector<double>& rows)
{
  std::map<std::string, std::pair<int, int>> where;  // column name -> offset and width in a row
  double defaults[256], *o = defaults;
  const ParticleRecord blank;
  forCheckpointFields([&](auto value, const char* cols) {
    const int offset = static_cast<int>(o - defaults);
    writeDoubles(blank.*value, o);
    const std::vector<std::string> names = split(cols);
    const int width = static_cast<int>(o - defaults) - offset, each = static_cast<int>(names.size()) == width ? 1 : width;
    for (std::size_t k = 0; k < names.size(); ++k) where[names[k]] = {offset + static_cast<int>(k) * each, each};
  });
  std::vector<std::pair<int, int>> source;  // per file column: offset in the file row, and where it goes
  int at = 0;
  for (const std::string& name : split(fileColumns)) {
    const auto it = where.find(name);
    if (it == where.end()) return "has the particle column " + name + ", unknown to this vpsolve (written by a newer version?)";
    for (int k = 0; k < it->second.second; ++k) source.push_back({at + k, it->second.first + k});
    at += it->second.second;
  }
  if (at != fileCols) return "has particle rows of " + std::to_string(fileCols) + " values, its columns name " + std::to_string(at);
  const std::size_t n = rows.size() / fileCols;
  std::vector<double> out(n * kParticleCols);
  for (std::size_t i = 0; i < n; ++i) {
    std::copy(defaults, defaults + kParticleCols, &out[i * kParticleCols]);
    for (const auto& [from, to] : source) out[i * kParticleCols + to] = rows[i * fileCols + from];
  }
  rows.swap(out);
  return "";
}

} // namespace

void saveParticles(StateWriter& w, const std::vector<ParticleRecord>& owned)
{
  std::vector<double> rows(kParticleCols * owned.size()), contacts, windows;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    double* o = &rows[kParticleCols * i];
    forCheckpointFields([&](auto value, const char*) { writeDoubles(owned[i].*value, o); });
    for (const WindowHistory& h : owned[i].windowHistory) {
      windows.push_back(double(owned[i].id));
      for (const Vec3& z : h.modes) windows.insert(windows.end(), {z.x, z.y, z.z});
      windows.insert(windows.end(), {h.contactChange.x, h.contactChange.y, h.contactChange.z});
    }
    for (const ContactSpring& c : owned[i].history)
      for (double v : {double(owned[i].id), double(c.partner), c.spring.x, c.spring.y, c.spring.z, double(c.departure)})
        contacts.push_back(v);
  }
  w.table(kParticles, rows, kParticleCols);
  w.table(kContacts, contacts, kContactCols);
  w.table(kWindows, windows, kWindowCols);
  w.text(kColumnsText, kParticleColumns);
}

std::vector<ParticleRecord> loadParticles(const StateReader& r)
{
  int cols = 0, contactCols = 0, windowCols = 0;
  std::vector<double> rows = r.table(kParticles, cols);
  const std::vector<double> contacts = r.table(kContacts, contactCols), windows = r.table(kWindows, windowCols);
  std::string names = r.text(kColumnsText);
  if (names.empty()) names = kParticleColumns;  // the oldest checkpoints do not name them
  if (!rows.empty()) {
    const std::string e = toCurrentLayout(names, cols, rows);
    if (!e.empty()) r.fail(e);
  }
  // The oldest contacts lack the departure state, the first window histories the contact's change.
  if (contactCols != 0 && contactCols != kContactCols && contactCols != kContactCols - 1)
    r.fail("dataset contacts has " + std::to_string(contactCols) + " columns, expected " + std::to_string(kContactCols));
  if (windowCols != 0 && windowCols != kWindowCols && windowCols != kWindowCols - 3)
    r.fail(std::string("dataset ") + kWindows + " has " + std::to_string(windowCols) + " columns, expected " + std::to_string(kWindowCols));

  std::vector<ParticleRecord> particles;
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i * kParticleCols < rows.size(); ++i) {
    ParticleRecord& p = particles.emplace_back();
    const double* o = &rows[kParticleCols * i];
    forCheckpointFields([&](auto value, const char*) { readDoubles(o, p.*value); });
    if (r.version() < 2) p.flags &= ~kTouching;  // another meaning in version 1
    index[p.id] = i;
  }
  for (std::size_t k = 0; contactCols > 0 && k + contactCols <= contacts.size(); k += contactCols) {
    const auto it = index.find(static_cast<std::int64_t>(contacts[k]));
    if (it == index.end()) r.fail("has a contact spring of an unknown particle (damaged checkpoint)");
    const double departure = contactCols == kContactCols ? contacts[k + 5] : 0;
    if (!(departure >= 0 && departure <= (kPairImpact | kPairLeaving)))
      r.fail("has a contact with an invalid departure state (damaged checkpoint)");
    particles[it->second].history.push_back({static_cast<std::int64_t>(contacts[k + 1]), Vec3{contacts[k + 2], contacts[k + 3], contacts[k + 4]},
                                             static_cast<std::uint8_t>(departure)});
  }
  for (std::size_t k = 0; windowCols > 0 && k + windowCols <= windows.size(); k += windowCols) {
    const auto it = index.find(static_cast<std::int64_t>(windows[k]));
    if (it == index.end() || !particles[it->second].windowHistory.empty())
      r.fail("has a window history of an unknown particle, or two of one (damaged checkpoint)");
    WindowHistory& h = particles[it->second].windowHistory.emplace_back();
    const double* o = &windows[k + 1];
    for (Vec3& z : h.modes) readDoubles(o, z);
    if (windowCols == kWindowCols) readDoubles(o, h.contactChange);
  }
  return particles;
}

} // namespace vp
