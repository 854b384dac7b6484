#include "vp/io/Checkpoint.hpp"
#include "vp/core/Broadcast.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/io/OutputDir.hpp"
#include "vp/io/RunRecord.hpp"
#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>
#include <petscviewerhdf5.h>
#include <unistd.h>

namespace vp {

namespace {

const char* const kFormat = "vpsolve checkpoint";
// Version 2 adds the contacts' departure column and the window_history dataset, which a version 1
// reader would drop without a word (late version 1 files may have them; they read with what they
// have), and flag 32 is kTouching (it was the window history's).
constexpr int kVersion = 2;
constexpr int kOldestVersion = 1;
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

// The particle rows of a checkpoint (named by its particle_columns attribute) in this build's layout:
// a column is found by its name, so a field added to ParticleFields.hpp reads from older checkpoints
// with its default value (a new field needs no version change). Returns an error, or "".
std::string toCurrentLayout(const std::string& fileColumns, hsize_t fileCols, std::vector<double>& rows)
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
  std::vector<std::pair<int, int>> source;  // per file column name: offset in the file row, and where it goes
  int at = 0;
  for (const std::string& name : split(fileColumns)) {
    const auto it = where.find(name);
    if (it == where.end()) return "has the particle column " + name + ", unknown to this vpsolve (written by a newer version?)";
    for (int k = 0; k < it->second.second; ++k) source.push_back({at + k, it->second.first + k});
    at += it->second.second;
  }
  if (at != static_cast<int>(fileCols)) return "has particle rows of " + std::to_string(fileCols) + " values, its columns name " + std::to_string(at);
  const std::size_t n = rows.size() / fileCols;
  std::vector<double> out(n * kParticleCols);
  for (std::size_t i = 0; i < n; ++i) {
    std::copy(defaults, defaults + kParticleCols, &out[i * kParticleCols]);
    for (const auto& [from, to] : source) out[i * kParticleCols + to] = rows[i * fileCols + from];
  }
  rows.swap(out);
  return "";
}
constexpr int kContactCols = 6;  // id, partner id, spring x, y, z, departure state (absent from the oldest files)
// id, the Basset modes' x, y, z by mode, the velocity change of a contact under way (absent in the
// dataset's first form: none); rows only for particles in a window (the dataset is absent from the
// oldest files: none were).
constexpr int kWindowCols = 4 + 3 * kBassetModes;
const char* const kWindowDataset = "window_history";

void pack(const ParticleRecord& r, double* o)
{
  forCheckpointFields([&](auto value, const char*) { writeDoubles(r.*value, o); });
}

ParticleRecord unpack(const double* o)
{
  ParticleRecord r;
  forCheckpointFields([&](auto value, const char*) { readDoubles(o, r.*value); });
  return r;
}

std::vector<double> packRun(const RunState& s)
{
  return {double(s.step), s.time, s.dtOld, s.nextOutputTime, s.nextCheckpointTime, double(s.lastOutputStep)};
}

void unpackRun(const std::vector<double>& v, RunState& s)
{
  s.step = static_cast<int>(v[0]);
  s.time = v[1];
  s.dtOld = v[2];
  s.nextOutputTime = v[3];
  s.nextCheckpointTime = v[4];
  s.lastOutputStep = static_cast<int>(v[5]);
}

const char* const kIncrementOld = "velocity_increment_old";

const char* const kRunAttribute = "run";  // step, time, dt_old, next_output_time, next_checkpoint_time, last_output_step

std::vector<std::pair<const char*, Vec>> named(const FluidState& f)
{
  std::vector<std::pair<const char*, Vec>> v = {{"velocity", f.velocity}, {"pressure", f.pressure},
                                                {"convection_old", f.convectionOld}, {"pressure_increment", f.pressureIncrement},
                                                {"velocity_increment", f.velocityIncrement}};
  if (f.velocityIncrementOld) v.push_back({kIncrementOld, f.velocityIncrementOld});
  return v;
}

std::string historyName(std::size_t i) { return "pressure_history_" + std::to_string(i); }

std::string list(const double* v, int n)
{
  std::string s;
  for (int i = 0; i < n; ++i) s += (i ? "," : "") + formatNumber(v[i]);
  return s;
}

// Reads the dataset's last value: a truncated file fails here rather than in the parallel load.
bool lastValueReadable(hid_t ds, hid_t space)
{
  hsize_t dims[8], start[8], count[8];
  const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
  if (rank < 1 || rank > 8) return false;
  for (int d = 0; d < rank; ++d) start[d] = dims[d] - 1, count[d] = 1;
  hid_t fspace = H5Scopy(space);
  H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
  const hsize_t one = 1;
  hid_t mspace = H5Screate_simple(1, &one, nullptr);
  double value;
  const bool ok = H5Dread(ds, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, &value) >= 0;
  H5Sclose(mspace);
  H5Sclose(fspace);
  return ok;
}

void broadcast(MPI_Comm comm, std::vector<double>& v)
{
  unsigned long n = v.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG, 0, comm);
  v.resize(n);
  if (n) MPI_Bcast(v.data(), static_cast<int>(n), MPI_DOUBLE, 0, comm);
}

} // namespace

CheckpointWriter::CheckpointWriter(MPI_Comm comm, std::string dir, int keep) : comm_(comm), dir_(std::move(dir)), keep_(keep)
{
  // A restart continues the count of the directory's checkpoints (a run in pieces keeps K in all).
  std::map<long, std::string> found;
  for (const std::string& name : runOutputs(dir_))
    if (name.rfind("checkpoint_", 0) == 0 && name != "checkpoint_latest.h5") found[std::stol(name.substr(11))] = dir_ + "/" + name;
  for (const auto& f : found) written_.push_back(f.second);
}

void CheckpointWriter::writeFile(const std::string& tmp, const Grid& grid, const BoundaryConfig& bc, const RunState& run,
                                 const FluidState& fluid, const std::vector<ParticleRecord>& owned)
{
  PetscViewer viewer;
  VP_CALL(PetscViewerHDF5Open(comm_, tmp.c_str(), FILE_MODE_WRITE, &viewer));
  for (auto [n, v] : named(fluid)) {
    VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(v), n));
    VP_CALL(VecView(v, viewer));
  }
  for (std::size_t i = 0; i < fluid.pressureHistory.size(); ++i) {
    // The history's own vectors: named only for the write, they keep the name.
    VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(fluid.pressureHistory[i]), historyName(i).c_str()));
    VP_CALL(VecView(fluid.pressureHistory[i], viewer));
  }
  hid_t file;
  VP_CALL(PetscViewerHDF5GetFileId(viewer, &file));

  // Particles and their springs: one block of rows per rank.
  std::vector<double> rows(kParticleCols * owned.size()), contacts, windows;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    pack(owned[i], &rows[kParticleCols * i]);
    for (const WindowHistory& h : owned[i].windowHistory) {
      windows.push_back(double(owned[i].id));
      for (const Vec3& z : h.modes) windows.insert(windows.end(), {z.x, z.y, z.z});
      windows.insert(windows.end(), {h.contactChange.x, h.contactChange.y, h.contactChange.z});
    }
    for (const ContactSpring& c : owned[i].history)
      for (double v : {double(owned[i].id), double(c.partner), c.spring.x, c.spring.y, c.spring.z, double(c.departure)})
        contacts.push_back(v);
  }
  int rank;
  MPI_Comm_rank(comm_, &rank);
  auto table = [&](const char* dataset, const std::vector<double>& data, long cols) {
    const long n = static_cast<long>(data.size()) / cols;
    long offset = 0, total = 0;
    MPI_Exscan(&n, &offset, 1, MPI_LONG, MPI_SUM, comm_);
    MPI_Allreduce(&n, &total, 1, MPI_LONG, MPI_SUM, comm_);
    if (rank == 0) offset = 0;
    h5::writeRows(file, dataset, H5T_NATIVE_DOUBLE, data.data(), total, offset, n, cols);
  };
  table("particles", rows, kParticleCols);
  table("contacts", contacts, kContactCols);
  table(kWindowDataset, windows, kWindowCols);
  // The snapshot lists are the same on every rank: rank 0 writes them.
  const std::vector<double> none;
  table("field_snapshots", rank == 0 ? run.fieldSnapshots : none, 2);
  table("particle_snapshots", rank == 0 ? run.particleSnapshots : none, 3);
  h5::writeAttribute(file, "format", kFormat);
  h5::writeAttribute(file, "version", &kVersion, 1);
  h5::writeAttribute(file, "particle_columns", kParticleColumns);
  const std::vector<double> r = packRun(run);
  h5::writeAttribute(file, kRunAttribute, r.data(), static_cast<int>(r.size()));
  h5::writeAttribute(file, "penalization_floor", &run.penalizationFloor, 1);
  int n[3], types[6];
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) n[d] = grid.n(d), lo[d] = grid.lo(d), hi[d] = grid.hi(d);
  for (int f = 0; f < 6; ++f) types[f] = static_cast<int>(bc.type[f]);
  h5::writeAttribute(file, "grid_n", n, 3);
  h5::writeAttribute(file, "grid_lo", lo, 3);
  h5::writeAttribute(file, "grid_hi", hi, 3);
  h5::writeAttribute(file, "boundary_types", types, 6);
  h5::writeAttribute(file, "setup_options", setupOptionsText());
  h5::writeAttribute(file, "vpsolve_run", runRecord());
  VP_CALL(PetscViewerDestroy(&viewer));
}

void CheckpointWriter::write(const Grid& grid, const BoundaryConfig& bc, const RunState& run, const FluidState& fluid,
                             const std::vector<ParticleRecord>& owned)
{
  const std::string name = h5::stepFile("checkpoint", run.step), path = dir_ + "/" + name, tmp = path + ".tmp";
  int rank;
  MPI_Comm_rank(comm_, &rank);
  try {
    QuietPetscErrors quiet;
    writeFile(tmp, grid, bc, run, fluid, owned);
  } catch (const std::exception& e) {
    // The earlier checkpoints stay; only the unfinished file goes.
    if (rank == 0) std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + tmp + " (" + e.what() + "; disk full?); earlier checkpoints are kept");
  }
  MPI_Barrier(comm_);
  if (rank == 0) {
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot rename " + tmp + " to " + path);
    const std::string latest = dir_ + "/checkpoint_latest.h5", link = latest + ".tmp";
    ::unlink(link.c_str());
    if (::symlink(name.c_str(), link.c_str()) != 0 || std::rename(link.c_str(), latest.c_str()) != 0)
      throw std::runtime_error("cannot point " + latest + " to " + name);
    written_.erase(std::remove(written_.begin(), written_.end(), path), written_.end());  // a step written again
    written_.push_back(path);
    while (static_cast<int>(written_.size()) > keep_) {
      std::remove(written_.front().c_str());
      written_.pop_front();
    }
  }
  MPI_Barrier(comm_);
}

CheckpointReader::CheckpointReader(MPI_Comm comm, const std::string& path, const Config& cfg) : comm_(comm), path_(path)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  std::vector<double> header, rows, contacts, windows, fieldSnaps, particleSnaps;
  int contactCols = kContactCols, windowCols = kWindowCols, version = 0;
  double floor = 0;  // penalization_floor (0: not in the checkpoint)
  if (rank == 0) {
    h5::QuietErrors quiet;
    hid_t file = -1;
    if (::access(path.c_str(), R_OK) != 0)
      error = "cannot read '" + path + "' (no such file, or not readable)";
    else if (H5Fis_hdf5(path.c_str()) <= 0 || (file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) < 0)
      error = "'" + path + "' is not an HDF5 file (damaged, or not a checkpoint)";
    std::string format;
    int n[3], types[6];
    double lo[3], hi[3];
    header.resize(6);
    if (error.empty() && (!h5::readAttribute(file, "format", format) || format != kFormat))
      error = "'" + path + "' is not a vpsolve checkpoint (no format attribute '" + kFormat + "')";
    else if (error.empty() && (!h5::readAttribute(file, "version", &version, 1) || version < kOldestVersion || version > kVersion))
      error = "'" + path + "' is checkpoint version " + std::to_string(version) + ", this vpsolve reads versions " +
              std::to_string(kOldestVersion) + " to " + std::to_string(kVersion);
    else if (error.empty() && (!h5::readAttribute(file, kRunAttribute, header.data(), 6) || !h5::readAttribute(file, "grid_n", n, 3) ||
                               !h5::readAttribute(file, "grid_lo", lo, 3) || !h5::readAttribute(file, "grid_hi", hi, 3) ||
                               !h5::readAttribute(file, "boundary_types", types, 6)))
      error = "'" + path + "' lacks run or grid attributes (damaged checkpoint)";
    if (error.empty()) {
      const double cn[3] = {double(cfg.grid.n[0]), double(cfg.grid.n[1]), double(cfg.grid.n[2])};
      const double fn[3] = {double(n[0]), double(n[1]), double(n[2])};
      bool sameBc = true;
      for (int f = 0; f < 6; ++f) sameBc = sameBc && types[f] == static_cast<int>(cfg.bc.type[f]);
      if (cn[0] != fn[0] || cn[1] != fn[1] || cn[2] != fn[2])
        error = "'" + path + "' was written for -grid_n " + list(fn, 3) + ", this run has -grid_n " + list(cn, 3);
      else if (lo[0] != cfg.grid.lo[0] || lo[1] != cfg.grid.lo[1] || lo[2] != cfg.grid.lo[2] || hi[0] != cfg.grid.hi[0] ||
               hi[1] != cfg.grid.hi[1] || hi[2] != cfg.grid.hi[2])
        error = "'" + path + "' was written for the box -grid_lo " + list(lo, 3) + " -grid_hi " + list(hi, 3) + ", this run has -grid_lo " +
                list(cfg.grid.lo.data(), 3) + " -grid_hi " + list(cfg.grid.hi.data(), 3);
      else if (!sameBc)
        error = "'" + path + "' was written with other boundary conditions (-bc_xlo ... -bc_zhi must match the original run)";
    }
    // The fluid datasets: present and of the grid's size.
    const double cells = double(cfg.grid.n[0]) * cfg.grid.n[1] * cfg.grid.n[2];
    for (auto [name, dof] : {std::pair<const char*, int>{"velocity", 3}, {"pressure", 1}, {"convection_old", 3}, {"pressure_increment", 1}}) {
      if (!error.empty()) break;
      hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
      if (ds < 0) {
        error = "'" + path + "' lacks the dataset " + name + " (damaged checkpoint)";
        break;
      }
      hid_t sp = H5Dget_space(ds);
      if (double(H5Sget_simple_extent_npoints(sp)) != cells * dof)
        error = "'" + path + "' dataset " + name + " does not match the grid (damaged checkpoint)";
      else if (!lastValueReadable(ds, sp))
        error = "'" + path + "' dataset " + name + " cannot be read (truncated or damaged checkpoint)";
      H5Sclose(sp);
      H5Dclose(ds);
    }
    hsize_t r = 0, c = 0;
    for (auto [name, data, cols] : {std::tuple<const char*, std::vector<double>*, hsize_t>{"particles", &rows, kParticleCols},
                                    {"contacts", &contacts, kContactCols}, {"field_snapshots", &fieldSnaps, 2},
                                    {"particle_snapshots", &particleSnaps, 3}}) {
      if (!error.empty()) break;
      const std::string e = h5::readTable(file, name, *data, r, c);
      if (!e.empty()) error = "'" + path + "' " + e + " (damaged checkpoint)";
      else if (data == &contacts && r > 0 && c == kContactCols - 1) contactCols = kContactCols - 1;  // before the departure state
      else if (data == &rows) {
        std::string names = kParticleColumns;  // the oldest checkpoints do not name them
        h5::readAttribute(file, "particle_columns", names);
        const std::string e2 = r > 0 ? toCurrentLayout(names, c, rows) : "";
        if (!e2.empty()) error = "'" + path + "' " + e2;
      } else if (r > 0 && c != cols) error = "'" + path + "' dataset " + name + " has " + std::to_string(c) + " columns, expected " + std::to_string(cols);
    }
    if (error.empty() && H5Lexists(file, kWindowDataset, H5P_DEFAULT) > 0) {
      const std::string e = h5::readTable(file, kWindowDataset, windows, r, c);
      if (!e.empty()) error = "'" + path + "' " + e + " (damaged checkpoint)";
      else if (r > 0 && c == kWindowCols - 3) windowCols = kWindowCols - 3;  // before the contact's change
      else if (r > 0 && c != kWindowCols) error = "'" + path + "' dataset " + kWindowDataset + " has " + std::to_string(c) + " columns, expected " + std::to_string(kWindowCols);
    }
    // Older checkpoints lack these: their set-up is not compared, their floor restarts from the state.
    if (error.empty()) h5::readAttribute(file, "setup_options", setup_);
    if (error.empty()) h5::readAttribute(file, "penalization_floor", &floor, 1);
    if (file >= 0) H5Fclose(file);
  }
  broadcast(comm, error);
  if (!error.empty()) failOption("-restart", error);
  broadcast(comm, setup_);
  for (std::vector<double>* v : {&header, &rows, &contacts, &windows, &fieldSnaps, &particleSnaps}) broadcast(comm, *v);
  MPI_Bcast(&floor, 1, MPI_DOUBLE, 0, comm);
  MPI_Bcast(&version, 1, MPI_INT, 0, comm);
  unpackRun(header, run_);
  run_.penalizationFloor = floor;
  run_.fieldSnapshots = fieldSnaps;
  run_.particleSnapshots = particleSnaps;
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i * kParticleCols < rows.size(); ++i) {
    particles_.push_back(unpack(&rows[kParticleCols * i]));
    if (version < 2) particles_.back().flags &= ~kTouching;  // another meaning in version 1
    index[particles_.back().id] = i;
  }
  MPI_Bcast(&contactCols, 1, MPI_INT, 0, comm);
  MPI_Bcast(&windowCols, 1, MPI_INT, 0, comm);
  for (std::size_t k = 0; k + contactCols <= contacts.size(); k += contactCols) {
    const auto it = index.find(static_cast<std::int64_t>(contacts[k]));
    if (it == index.end()) failOption("-restart", "'" + path + "' has a contact spring of an unknown particle (damaged checkpoint)");
    const double departure = contactCols == kContactCols ? contacts[k + 5] : 0;
    if (!(departure >= 0 && departure <= (kPairImpact | kPairLeaving)))
      failOption("-restart", "'" + path + "' has a contact with an invalid departure state (damaged checkpoint)");
    particles_[it->second].history.push_back({static_cast<std::int64_t>(contacts[k + 1]), Vec3{contacts[k + 2], contacts[k + 3], contacts[k + 4]},
                                             static_cast<std::uint8_t>(departure)});
  }
  for (std::size_t k = 0; k + windowCols <= windows.size(); k += windowCols) {
    const auto it = index.find(static_cast<std::int64_t>(windows[k]));
    if (it == index.end() || !particles_[it->second].windowHistory.empty())
      failOption("-restart", "'" + path + "' has a window history of an unknown particle, or two of one (damaged checkpoint)");
    WindowHistory& h = particles_[it->second].windowHistory.emplace_back();
    const double* o = &windows[k + 1];
    for (Vec3& z : h.modes) readDoubles(o, z);
    if (windowCols == kWindowCols) readDoubles(o, h.contactChange);
  }
}

bool CheckpointReader::loadFluid(const FluidState& fluid) const
{
  PetscViewer viewer;
  VP_CALL(PetscViewerHDF5Open(comm_, path_.c_str(), FILE_MODE_READ, &viewer));
  bool old = false;
  for (auto [n, v] : named(fluid)) {
    if (v == fluid.velocityIncrementOld) {
      PetscBool has;
      VP_CALL(PetscViewerHDF5HasDataset(viewer, (std::string("/") + n).c_str(), &has));
      if (!(old = has)) continue;
    }
    VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(v), n));
    VP_CALL(VecLoad(v, viewer));
  }
  VP_CALL(PetscViewerDestroy(&viewer));
  return old;
}

std::vector<Vec> CheckpointReader::loadPressureHistory(Vec like) const
{
  std::vector<Vec> history;
  PetscViewer viewer;
  VP_CALL(PetscViewerHDF5Open(comm_, path_.c_str(), FILE_MODE_READ, &viewer));
  for (std::size_t i = 0;; ++i) {
    PetscBool has;
    VP_CALL(PetscViewerHDF5HasDataset(viewer, ("/" + historyName(i)).c_str(), &has));
    if (!has) break;
    Vec v;
    VP_CALL(VecDuplicate(like, &v));
    VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(v), historyName(i).c_str()));
    VP_CALL(VecLoad(v, viewer));
    history.push_back(v);
  }
  VP_CALL(PetscViewerDestroy(&viewer));
  return history;
}

} // namespace vp
