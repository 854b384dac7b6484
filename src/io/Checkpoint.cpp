#include "vp/io/Checkpoint.hpp"
#include "vp/core/Broadcast.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/io/OutputDir.hpp"
#include "vp/io/RunRecord.hpp"
#include <algorithm>
#include <cstdio>
#include <optional>
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
const char* const kRunAttribute = "run";  // step, time, dt_old, next_output_time, next_checkpoint_time, last_output_step

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

// One open checkpoint file being written: the components' parts go into it by name.
class FileWriter : public StateWriter {
public:
  FileWriter(MPI_Comm comm, const std::string& path) : comm_(comm)
  {
    MPI_Comm_rank(comm, &rank_);
    VP_CALL(PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_WRITE, &viewer_));
    VP_CALL(PetscViewerHDF5GetFileId(viewer_, &file_));
  }
  ~FileWriter() override { PetscViewerDestroy(&viewer_); }
  FileWriter(const FileWriter&) = delete;
  FileWriter& operator=(const FileWriter&) = delete;
  hid_t file() const { return file_; }

  void vector(const std::string& name, Vec v) override
  {
    // The component's own vector: named only for the write, it keeps the name.
    VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(v), name.c_str()));
    VP_CALL(VecView(v, viewer_));
  }
  void table(const std::string& name, const std::vector<double>& rows, int cols) override
  {
    const long n = static_cast<long>(rows.size()) / cols;
    long offset = 0, total = 0;
    MPI_Exscan(&n, &offset, 1, MPI_LONG, MPI_SUM, comm_);
    MPI_Allreduce(&n, &total, 1, MPI_LONG, MPI_SUM, comm_);
    if (rank_ == 0) offset = 0;
    h5::writeRows(file_, name.c_str(), H5T_NATIVE_DOUBLE, rows.data(), total, offset, n, cols);
  }
  void text(const std::string& name, const std::string& value) override { h5::writeAttribute(file_, name.c_str(), value); }

private:
  MPI_Comm comm_;
  int rank_ = 0;
  PetscViewer viewer_ = nullptr;
  hid_t file_ = -1;
};

// Rank 0's read-only handle of the checkpoint for the length of a scope.
struct ReadOnlyFile {
  explicit ReadOnlyFile(const std::string& path) : id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {}
  ~ReadOnlyFile()
  {
    if (id >= 0) H5Fclose(id);
  }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
  hid_t id;
};

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
                                 const StateParts& parts)
{
  FileWriter w(comm_, tmp);
  parts(w);
  // The snapshot lists are the same on every rank: rank 0 writes them.
  int rank;
  MPI_Comm_rank(comm_, &rank);
  const std::vector<double> none;
  w.table("field_snapshots", rank == 0 ? run.fieldSnapshots : none, 2);
  w.table("particle_snapshots", rank == 0 ? run.particleSnapshots : none, 3);
  const hid_t file = w.file();
  h5::writeAttribute(file, "format", kFormat);
  h5::writeAttribute(file, "version", &kVersion, 1);
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
}

void CheckpointWriter::write(const Grid& grid, const BoundaryConfig& bc, const RunState& run, const StateParts& parts)
{
  const std::string name = h5::stepFile("checkpoint", run.step), path = dir_ + "/" + name, tmp = path + ".tmp";
  int rank;
  MPI_Comm_rank(comm_, &rank);
  try {
    QuietPetscErrors quiet;
    writeFile(tmp, grid, bc, run, parts);
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
  MPI_Comm_rank(comm, &rank_);
  std::string error;
  std::vector<double> header(6);
  double floor = 0;  // penalization_floor (0: not in the checkpoint)
  if (rank_ == 0) {
    h5::QuietErrors quiet;
    if (::access(path.c_str(), R_OK) != 0)
      error = "cannot read '" + path + "' (no such file, or not readable)";
    else if (H5Fis_hdf5(path.c_str()) <= 0)
      error = "'" + path + "' is not an HDF5 file (damaged, or not a checkpoint)";
    std::optional<ReadOnlyFile> f;
    if (error.empty() && f.emplace(path).id < 0) error = "'" + path + "' is not an HDF5 file (damaged, or not a checkpoint)";
    const hid_t file = f ? f->id : -1;
    std::string format;
    int n[3], types[6];
    double lo[3], hi[3];
    if (error.empty() && (!h5::readAttribute(file, "format", format) || format != kFormat))
      error = "'" + path + "' is not a vpsolve checkpoint (no format attribute '" + kFormat + "')";
    else if (error.empty() && (!h5::readAttribute(file, "version", &version_, 1) || version_ < kOldestVersion || version_ > kVersion))
      error = "'" + path + "' is checkpoint version " + std::to_string(version_) + ", this vpsolve reads versions " +
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
    // Older checkpoints lack these: their set-up is not compared, their floor restarts from the state.
    if (error.empty()) h5::readAttribute(file, "setup_options", setup_);
    if (error.empty()) h5::readAttribute(file, "penalization_floor", &floor, 1);
  }
  broadcast(comm, error);
  if (!error.empty()) failOption("-restart", error);
  broadcast(comm, setup_);
  broadcast(comm, header);
  MPI_Bcast(&floor, 1, MPI_DOUBLE, 0, comm);
  MPI_Bcast(&version_, 1, MPI_INT, 0, comm);
  unpackRun(header, run_);
  run_.penalizationFloor = floor;
  int cols;
  run_.fieldSnapshots = table("field_snapshots", cols);
  if (cols != 0 && cols != 2) fail("dataset field_snapshots has " + std::to_string(cols) + " columns, expected 2");
  run_.particleSnapshots = table("particle_snapshots", cols);
  if (cols != 0 && cols != 3) fail("dataset particle_snapshots has " + std::to_string(cols) + " columns, expected 3");
}

void CheckpointReader::fail(const std::string& what) const { failOption("-restart", "'" + path_ + "' " + what); }

bool CheckpointReader::has(const std::string& name) const
{
  int found = 0;
  if (rank_ == 0) {
    h5::QuietErrors quiet;
    const ReadOnlyFile f(path_);
    found = f.id >= 0 && H5Lexists(f.id, name.c_str(), H5P_DEFAULT) > 0;
  }
  MPI_Bcast(&found, 1, MPI_INT, 0, comm_);
  return found != 0;
}

void CheckpointReader::vector(const std::string& name, Vec v) const
{
  // Checked on one rank before the parallel load, which would fail without a word.
  PetscInt size;
  VP_CALL(VecGetSize(v, &size));
  std::string error;
  if (rank_ == 0) {
    h5::QuietErrors quiet;
    const ReadOnlyFile f(path_);
    const hid_t ds = f.id >= 0 ? H5Dopen2(f.id, name.c_str(), H5P_DEFAULT) : -1;
    if (ds < 0)
      error = "lacks the dataset " + name + " (damaged checkpoint)";
    else {
      const hid_t sp = H5Dget_space(ds);
      if (H5Sget_simple_extent_npoints(sp) != static_cast<hssize_t>(size))
        error = "dataset " + name + " does not match the grid (damaged checkpoint)";
      else if (!lastValueReadable(ds, sp))
        error = "dataset " + name + " cannot be read (truncated or damaged checkpoint)";
      H5Sclose(sp);
      H5Dclose(ds);
    }
  }
  broadcast(comm_, error);
  if (!error.empty()) fail(error);
  PetscViewer viewer;
  VP_CALL(PetscViewerHDF5Open(comm_, path_.c_str(), FILE_MODE_READ, &viewer));
  VP_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(v), name.c_str()));
  VP_CALL(VecLoad(v, viewer));
  VP_CALL(PetscViewerDestroy(&viewer));
}

std::vector<double> CheckpointReader::table(const std::string& name, int& cols) const
{
  std::vector<double> values;
  std::string error;
  hsize_t r = 0, c = 0;
  if (rank_ == 0) {
    h5::QuietErrors quiet;
    const ReadOnlyFile f(path_);
    if (f.id >= 0 && H5Lexists(f.id, name.c_str(), H5P_DEFAULT) > 0) {
      error = h5::readTable(f.id, name.c_str(), values, r, c);
      if (!error.empty()) error += " (damaged checkpoint)";
    }
  }
  broadcast(comm_, error);
  if (!error.empty()) fail(error);
  broadcast(comm_, values);
  cols = static_cast<int>(r > 0 ? c : 0);
  MPI_Bcast(&cols, 1, MPI_INT, 0, comm_);
  return values;
}

std::string CheckpointReader::text(const std::string& name) const
{
  std::string value;
  if (rank_ == 0) {
    h5::QuietErrors quiet;
    const ReadOnlyFile f(path_);
    if (f.id >= 0) h5::readAttribute(f.id, name.c_str(), value);
  }
  broadcast(comm_, value);
  return value;
}

} // namespace vp
