#include "vp/io/RunRecord.hpp"
#include "vp/Version.hpp"
#include "vp/core/Broadcast.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace vp {

namespace {

std::string commandLine, startDate;

} // namespace

void setCommandLine(int argc, char** argv)
{
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&now));
  startDate = date;
  commandLine.clear();
  for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + std::string(argv[i]);
}

std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      out += b;
    } else
      out += c;
  }
  return out + "\"";
}

std::string runRecordJson(MPI_Comm comm, const std::string& end)
{
  int size;
  MPI_Comm_size(comm, &size);
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  std::string j = "{\n  \"program\": \"vpsolve\",\n  \"version\": " + jsonString(VP_VERSION) + ",\n  \"date\": " + jsonString(startDate) +
                  ",\n  \"host\": " + jsonString(host) + ",\n  \"ranks\": " + std::to_string(size) +
                  ",\n  \"command\": " + jsonString(commandLine) + ",\n  \"options\": {";
  const auto& all = registeredOptions();
  for (std::size_t i = 0; i < all.size(); ++i)
    j += std::string(i ? "," : "") + "\n    " + jsonString(all[i].name) + ": {\"value\": " + jsonString(all[i].value) +
         ", \"given\": " + (all[i].given ? "true" : "false") + "}";
  char* petsc = nullptr;
  PetscOptionsGetAll(nullptr, &petsc);
  j += "\n  },\n  \"petsc_options\": " + jsonString(petsc ? petsc : "");
  PetscFree(petsc);
  if (!end.empty()) j += ",\n  " + end;
  return j + "\n}\n";
}

std::string runEndJson(const RunEnd& e)
{
  std::string stages;
  for (const auto& [name, seconds] : e.stageSeconds) stages += std::string(stages.empty() ? "" : ", ") + jsonString(name) + ": " + formatNumber(seconds);
  std::string j = "\"stop_reason\": " + jsonString(e.stopReason) + ",\n  \"step\": " + std::to_string(e.step) +
                  ",\n  \"time\": " + formatNumber(e.time) + ",\n  \"steps_this_run\": " + std::to_string(e.stepsThisRun) +
                  ",\n  \"wall_seconds\": " + formatNumber(e.wallSeconds) + ",\n  \"loop_seconds\": " + formatNumber(e.loopSeconds) +
                  ",\n  \"stage_seconds\": {" + stages + "}";
  if (e.fluid) j += ",\n  \"kinetic_energy\": " + formatNumber(e.kineticEnergy, 10);
  if (e.particles)
    j += ",\n  \"particles_at_start\": " + std::to_string(e.particlesAtStart) + ",\n  \"particles\": " + std::to_string(e.particleCount) +
         ",\n  \"particle_kinetic_energy\": " + formatNumber(e.particleKineticEnergy, 10);
  return j;
}

const std::string& runRecord()
{
  // Rank 0's (host and date differ between ranks; parallel HDF5 needs one value everywhere).
  static const std::string record = [] {
    int rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    std::string r = rank == 0 ? runRecordJson(PETSC_COMM_WORLD) : std::string();
    broadcast(PETSC_COMM_WORLD, r);
    return r;
  }();
  return record;
}

void writeRunRecord(MPI_Comm comm, const std::string& dir, const std::string& end)
{
  int rank, ok = 1;
  MPI_Comm_rank(comm, &rank);
  const std::string text = end.empty() ? runRecord() : runRecordJson(comm, end);
  if (rank == 0) {
    const std::string path = dir + "/run.json", tmp = path + ".tmp";
    std::ofstream out(tmp);
    out << text;
    out.close();
    std::error_code ec;
    if (!out) ok = 0;
    else std::filesystem::rename(tmp, path, ec);
    if (ec) ok = 0;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
  if (!ok) throw std::runtime_error("cannot write " + dir + "/run.json (disk full or no permission?)");
}

} // namespace vp
