#include "vp/io/OutputDir.hpp"
#include "vp/core/Broadcast.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <sys/statvfs.h>

namespace fs = std::filesystem;

namespace vp {

std::vector<std::string> runOutputs(const std::string& dir)
{
  static const std::regex names(R"((run\.json|diagnostics\.csv|probes\.csv|(fields|particles)\.xmf|)"
                                R"((fields|particles|checkpoint)_(\d{6,}|latest)\.h5|particle_\d+\.csv))");
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (std::regex_match(e.path().filename().string(), names)) out.push_back(e.path().filename().string());
  return out;
}

namespace {

// Rank 0 decides; every rank throws the same error.
void agree(MPI_Comm comm, std::string error)
{
  broadcast(comm, error);
  if (!error.empty()) throw InputError(error);
}

} // namespace

void checkOutputDir(MPI_Comm comm, const std::string& dir, const std::string& restart, bool overwrite)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0) {
    std::error_code ec;
    const std::vector<std::string> old = runOutputs(dir);
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      error = "option -output_dir: '" + dir + "' exists and is not a directory";
    else if (!old.empty() && !restart.empty() && !overwrite &&
             !fs::equivalent(fs::path(restart).parent_path().empty() ? "." : fs::path(restart).parent_path(), dir, ec))
      error = "option -restart: the checkpoint '" + restart + "' is not in -output_dir '" + dir + "', which holds another run; "
              "continue a run in its own directory, or choose an empty -output_dir";
    else if (!old.empty() && restart.empty() && !overwrite)
      error = "option -output_dir: '" + dir + "' holds another run (" + std::to_string(old.size()) + " files: " + old.front() +
              (old.size() > 1 ? ", ..." : "") + "); choose another -output_dir" +
              (fs::exists(dir + "/checkpoint_latest.h5", ec) ? ", continue it with -restart " + dir + "/checkpoint_latest.h5" : "") +
              ", or give -output_overwrite to replace it";
  }
  agree(comm, error);
}

void prepareOutputDir(MPI_Comm comm, const std::string& dir, bool restart, bool overwrite)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0) {
    std::error_code ec;
    if (overwrite && !restart)
      for (const auto& f : runOutputs(dir)) fs::remove(fs::path(dir) / f, ec);
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir, ec)) error = "option -output_dir: cannot create directory '" + dir + "'";
  }
  agree(comm, error);
}

void requireSpace(MPI_Comm comm, const std::string& dir, double bytes, const std::string& what)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  double free = HUGE_VAL;
  struct statvfs fs;
  if (rank == 0 && statvfs(dir.c_str(), &fs) == 0) free = double(fs.f_bavail) * double(fs.f_frsize);
  MPI_Bcast(&free, 1, MPI_DOUBLE, 0, comm);
  const double need = 1.1 * bytes + 1e6;  // HDF5 metadata and the index files
  if (free >= need) return;
  char msg[512];
  std::snprintf(msg, sizeof msg, "the file system of -output_dir '%s' has %.1f MB free, %s needs about %.1f MB: the run stops "
                "with the earlier outputs and checkpoints intact; free space, then continue with -restart %s/checkpoint_latest.h5",
                dir.c_str(), free / 1e6, what.c_str(), need / 1e6, dir.c_str());
  throw RunFailure(msg);
}

} // namespace vp
