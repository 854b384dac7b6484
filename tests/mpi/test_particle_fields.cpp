// Every field of ParticleFields.hpp survives what its sync flags promise: migration to another
// rank (kMigrate), ghost creation (kCreate) and the sub-step ghost update (kStep), and a checkpoint
// round trip (kCheckpoint, and the contact and window histories in their own datasets). Each field is set to
// values unique to the particle and the field, then compared bit for bit; the snapshot datasets
// (kSnapshot) are read back too.
#include "../support/DemFixtures.hpp"
#include "vp/core/Error.hpp"
#include "vp/io/Checkpoint.hpp"
#include "vp/io/ParticleWriter.hpp"
#include <hdf5.h>
#include "vp/particles/Exchange.hpp"
#include "vp/particles/ParticleCheckpoint.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstring>
#include <string>
#include <filesystem>

using namespace vp;
using namespace vp::test;

namespace {

double tag(std::int64_t id, int field, int k, int round) { return 1e5 * id + 10.0 * field + k + 0.125 * round; }

// Distinct values for particle id, field number f (round: a second set for the ghost update).
void fill(std::int64_t&, std::int64_t, int, int) {}  // the id is the identity
void fill(std::uint8_t& v, std::int64_t, int, int) { v = kResolvedForceOff | kTouching; }
void fill(double& v, std::int64_t id, int f, int round) { v = tag(id, f, 0, round); }
void fill(Vec3& v, std::int64_t id, int f, int round) { v = {tag(id, f, 0, round), tag(id, f, 1, round), tag(id, f, 2, round)}; }
void fill(Aspect& a, std::int64_t id, int f, int round) { a.value = tag(id, f, 0, round); }
void fill(Quaternion& q, std::int64_t id, int f, int round)
{
  q = {tag(id, f, 0, round), tag(id, f, 1, round), tag(id, f, 2, round), tag(id, f, 3, round)};
}
template <std::size_t N>  // wall springs, Basset modes
void fill(std::array<Vec3, N>& a, std::int64_t id, int f, int round)
{
  for (std::size_t k = 0; k < N; ++k) fill(a[k], id, 100 * f + int(k), round);
}
void fill(WindowModes& w, std::int64_t id, int f, int round)
{
  w.resize(1);
  fill(w.front().modes, id, f, round);
  fill(w.front().contactChange, id, 100 * f + kBassetModes, round);
}
void fill(ContactHistory& h, std::int64_t id, int f, int round)
{
  h = {{id + 1, {}, kPairImpact}, {id + 2, {}, kPairLeaving}};
  fill(h[0].spring, id, f, round);
  fill(h[1].spring, id, f + 1, round);
}

template <class T>
bool same(const T& a, const T& b)
{
  if constexpr (std::is_same_v<T, ContactHistory>) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (a[k].partner != b[k].partner || !same(a[k].spring, b[k].spring) || a[k].departure != b[k].departure) return false;
    return true;
  } else if constexpr (std::is_same_v<T, WindowModes>) {
    return a.size() == b.size() && (a.empty() || same(a.front(), b.front()));
  } else {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
  }
}

bool keepsShape(const std::string& name)
{
  // Identity, shape and position are set by the test itself (they decide ownership and mass).
  return name == "id" || name == "radius" || name == "aspect" || name == "density" || name == "x";
}

// Sets every field but id, radius, aspect, density and position; round 1 changes only the kStep fields.
void setFields(ParticleRecord& r, int round)
{
  int f = 0;
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo& info, auto sync) {
    ++f;
    if (keepsShape(info.name)) return;
    if (round == 0 || (decltype(sync)::value & kStep)) fill(r.*value, r.id, f, round);
  });
  if (r.id % 2 == 0) r.windowHistory.clear();  // outside a window: no row in the checkpoint's dataset
}

// Field by field: fields with any of the `sync` bits (or named in `also`) must equal `want`'s, the
// others their default; returns the names of those that do not.
template <unsigned Sync>
std::string mismatches(const ParticleRecord& got, const ParticleRecord& want, const std::vector<std::string>& also = {})
{
  std::string bad;
  const ParticleRecord blank;
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo& info, auto sync) {
    const bool carried = (decltype(sync)::value & Sync) != 0 || std::find(also.begin(), also.end(), info.name) != also.end();
    if (!same(got.*value, carried ? want.*value : blank.*value)) bad += std::string(" ") + info.name;
  });
  return bad;
}

ParticleRecord expected(std::int64_t id, Vec3 x, int round)
{
  ParticleRecord r = sphere(id, x, 0.01, 1000 + id);
  r.aspect.value = 1.5 + 0.01 * id;  // a spheroid's: distinct from the default a dropped field would read as
  setFields(r, 0);
  if (round) setFields(r, 1);
  return r;
}

} // namespace

TEST_CASE("Every particle field survives migration, ghosts and a checkpoint", "[mpi][particles][fields]")
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {12, 12, 12});
  Grid grid(comm, c.grid, c.bc);
  ParticleExchange ex(grid, 0.2);
  // Particles spread over the box on every rank's side; each rank creates those it owns.
  std::vector<Vec3> start, moved;
  for (int i = 0; i < 27; ++i) {
    const Vec3 x{0.15 + 0.35 * (i % 3), 0.15 + 0.35 * ((i / 3) % 3), 0.15 + 0.35 * (i / 9)};
    start.push_back(x);
    Vec3 y = x;  // 0.3 along every axis, towards the middle: most move to a neighbouring rank
    for (int d = 0; d < 3; ++d) y[d] += x[d] < 0.5 ? 0.3 : -0.3;
    moved.push_back(y);
  }
  ParticleStore s;
  for (int i = 0; i < 27; ++i)
    if (ex.owns(start[i])) s.append(expected(i, start[i], 0));
  s.nOwned = s.size();

  // Migration: every kMigrate field arrives; the new position too.
  for (std::size_t i = 0; i < s.nOwned; ++i) s.x[i] = moved[s.id[i]];
  ex.migrate(s);
  std::string bad;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const std::string m = mismatches<kMigrate>(s.record(i), expected(s.id[i], moved[s.id[i]], 0));
    if (!m.empty()) bad += " particle " + std::to_string(s.id[i]) + ":" + m;
  }
  INFO("after migration:" << bad);
  CHECK(allRanks(comm, bad.empty()));

  // Ghost creation carries the kCreate fields, the sub-step update the kStep fields.
  ex.createGhosts(s);
  std::string badGhost;
  for (std::size_t g = s.nOwned; g < s.size(); ++g) {
    const std::string m = mismatches<kCreate>(s.record(g), expected(s.id[g], moved[s.id[g]], 0));
    if (!m.empty()) badGhost += " ghost " + std::to_string(s.id[g]) + ":" + m;
  }
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    ParticleRecord r = s.record(i);
    setFields(r, 1);
    forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto value, const ParticleFieldInfo&, auto sync) {
      if constexpr ((decltype(sync)::value & kStep) != 0) (s.*field)[i] = r.*value;
    });
  }
  ex.updateGhosts(s);
  for (std::size_t g = s.nOwned; g < s.size(); ++g) {
    const std::string m = mismatches<kCreate>(s.record(g), expected(s.id[g], moved[s.id[g]], 1));
    if (!m.empty()) badGhost += " updated ghost " + std::to_string(s.id[g]) + ":" + m;
  }
  long ghosts = static_cast<long>(s.size() - s.nOwned), allGhosts = 0;
  MPI_Allreduce(&ghosts, &allGhosts, 1, MPI_LONG, MPI_SUM, comm);
  INFO("ghosts:" << badGhost);
  CHECK(allRanks(comm, badGhost.empty()));
  if (size > 1) CHECK(allGhosts > 0);
  s.dropGhosts();

  // Checkpoint: every kCheckpoint field and the contact history come back, on every rank.
  const std::string dir = "particle_fields_checkpoint";
  if (rank == 0) std::filesystem::create_directories(dir);
  MPI_Barrier(comm);
  std::vector<ParticleRecord> owned;
  for (std::size_t i = 0; i < s.nOwned; ++i) owned.push_back(s.record(i));
  RunState run;
  CheckpointWriter(comm, dir, 1).write(grid, c.bc, run, [&](StateWriter& w) { saveParticles(w, owned); });
  const std::vector<ParticleRecord> restored = loadParticles(CheckpointReader(comm, dir + "/checkpoint_latest.h5", c));
  std::string badCheckpoint;
  for (const ParticleRecord& r : restored) {
    // The contact and window histories are not checkpoint columns but have their own datasets:
    // they must come back too.
    const std::string m = mismatches<kCheckpoint>(r, expected(r.id, moved[r.id], 1), {"history", "windowHistory"});
    if (!m.empty()) badCheckpoint += " particle " + std::to_string(r.id) + ":" + m;
  }
  INFO("checkpoint:" << badCheckpoint);
  CHECK(restored.size() == 27);
  CHECK(allRanks(comm, badCheckpoint.empty()));
  // The window dataset's first form (without the contact's change, its last three columns) reads
  // with the modes and no change.
  if (rank == 0) {
    hid_t file = H5Fopen((dir + "/checkpoint_latest.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t ds = H5Dopen2(file, "window_history", H5P_DEFAULT), sp = H5Dget_space(ds);
    hsize_t dims[2];
    H5Sget_simple_extent_dims(sp, dims, nullptr);
    std::vector<double> all(dims[0] * dims[1]), first;
    CHECK(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()) >= 0);
    H5Sclose(sp);
    H5Dclose(ds);
    for (hsize_t r = 0; r < dims[0]; ++r) first.insert(first.end(), &all[r * dims[1]], &all[r * dims[1]] + dims[1] - 3);
    CHECK(H5Ldelete(file, "window_history", H5P_DEFAULT) >= 0);
    const hsize_t cut[2] = {dims[0], dims[1] - 3};
    sp = H5Screate_simple(2, cut, nullptr);
    ds = H5Dcreate2(file, "window_history", H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    CHECK(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, first.data()) >= 0);
    H5Dclose(ds);
    H5Sclose(sp);
    H5Fclose(file);
  }
  MPI_Barrier(comm);
  const std::vector<ParticleRecord> firstForm = loadParticles(CheckpointReader(comm, dir + "/checkpoint_latest.h5", c));
  bool modesKept = firstForm.size() == 27;
  for (const ParticleRecord& r : firstForm) {
    const WindowModes& want = expected(r.id, moved[r.id], 1).windowHistory;
    modesKept = modesKept && r.windowHistory.size() == want.size() &&
                (want.empty() || (same(r.windowHistory[0].modes, want[0].modes) && same(r.windowHistory[0].contactChange, Vec3{})));
  }
  CHECK(modesKept);
  // A version 1 checkpoint (from before the window history: no such dataset) reads as no particle
  // in a window, without the flag that meant another thing then; a version newer than this
  // reader's is refused, not read without what it adds.
  auto rewrite = [&](int version, bool dropWindows) {
    if (rank == 0) {
      hid_t file = H5Fopen((dir + "/checkpoint_latest.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
      if (dropWindows) CHECK(H5Ldelete(file, "window_history", H5P_DEFAULT) >= 0);
      hid_t attr = H5Aopen(file, "version", H5P_DEFAULT);
      CHECK(H5Awrite(attr, H5T_NATIVE_INT, &version) >= 0);
      H5Aclose(attr);
      H5Fclose(file);
    }
    MPI_Barrier(comm);
  };
  rewrite(1, true);
  const std::vector<ParticleRecord> older = loadParticles(CheckpointReader(comm, dir + "/checkpoint_latest.h5", c));
  bool noModes = older.size() == 27;
  for (const ParticleRecord& r : older) noModes = noModes && r.windowHistory.empty() && r.flags == kResolvedForceOff;
  CHECK(noModes);
  rewrite(3, false);
  CHECK_THROWS_WITH(CheckpointReader(comm, dir + "/checkpoint_latest.h5", c),
                    Catch::Contains("is checkpoint version 3, this vpsolve reads versions 1 to 2"));

  // Snapshot: every kSnapshot dataset holds the field's values, row by row in the file's id order.
  ParticleWriter(comm, dir).write(s, 1, 0.5);
  std::string badSnapshot;
  if (rank == 0) {
    hid_t file = H5Fopen((dir + "/particles_000001.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    std::vector<std::int64_t> ids(27);
    hid_t d = H5Dopen2(file, "id", H5P_DEFAULT);
    H5Dread(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, ids.data());
    H5Dclose(d);
    forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo& info, auto sync) {
      if constexpr ((decltype(sync)::value & kSnapshot) != 0) {
        using T = std::remove_reference_t<decltype(std::declval<ParticleRecord>().*value)>;
        if constexpr (!std::is_same_v<T, std::int64_t>) {
          const int w = doublesOf<T>();
          std::vector<double> rows(27 * w);
          hid_t ds = H5Dopen2(file, info.snapshot, H5P_DEFAULT);
          H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data());
          H5Dclose(ds);
          for (int i = 0; i < 27; ++i) {
            std::vector<double> want(w);
            double* o = want.data();
            writeDoubles(expected(ids[i], moved[ids[i]], 1).*value, o);
            if (std::memcmp(want.data(), &rows[i * w], w * sizeof(double)) != 0)
              badSnapshot += " " + std::string(info.snapshot) + "[" + std::to_string(ids[i]) + "]";
          }
        }
      }
    });
    H5Fclose(file);
  }
  INFO("snapshot:" << badSnapshot);
  CHECK(allRanks(comm, badSnapshot.empty()));
  MPI_Barrier(comm);
  if (rank == 0) std::filesystem::remove_all(dir);  // the test's files, wherever it runs
}
