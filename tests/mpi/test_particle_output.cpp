// Particle snapshots written in parallel read back complete (every id once, the right positions)
// and the XDMF index is a Polyvertex collection with relative paths and plain datasets.
#include "../support/DemFixtures.hpp"
#include "vp/io/ParticleWriter.hpp"
#include "vp/particles/Generators.hpp"
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <hdf5.h>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace vp;
using namespace vp::test;

TEST_CASE("Parallel particle snapshot and XDMF index", "[mpi][particles]")
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  int rank;
  MPI_Comm_rank(comm, &rank);
  Config c = boxConfig({0, 0, 0}, {0.1, 0.1, 0.1}, {6, 6, 6});
  LatticeInput lattice;
  lattice.lo = {0, 0, 0};
  lattice.hi = {0.1, 0.1, 0.1};
  lattice.spacing = 0.01;
  lattice.radius = 0.004;
  lattice.jitter = 0.5;
  lattice.seed = 1;
  Grid grid(comm, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, contactConfig(1e-3, 0.9, 0.3)), latticeParticles(lattice, 1000));
  dem.advance(0, 1e-5);
  long pid = getpid();
  MPI_Bcast(&pid, 1, MPI_LONG, 0, comm);
  const std::string dir = "scratch_particles_" + std::to_string(pid);  // under the working folder (the build tree)
  if (rank == 0) mkdir(dir.c_str(), 0755);
  MPI_Barrier(comm);
  ParticleWriter writer(comm, dir);
  writer.write(dem.particles(), 0, 0);
  writer.write(dem.particles(), 7, 1e-5);
  const std::vector<State> all = gatherState(comm, dem.particles());
  bool ok = true;
  std::string xmf;
  if (rank == 0) {
    hid_t file = H5Fopen((dir + "/particles_000007.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ok = file >= 0;
    std::vector<long long> id(1000);
    std::vector<double> x(3000);
    hid_t ds = H5Dopen2(file, "id", H5P_DEFAULT);
    ok = ok && H5Dread(ds, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, id.data()) >= 0;
    H5Dclose(ds);
    ds = H5Dopen2(file, "position", H5P_DEFAULT);
    ok = ok && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()) >= 0;
    H5Dclose(ds);
    H5Fclose(file);
    std::vector<int> seen(1000, 0);
    for (int r = 0; r < 1000 && ok; ++r) {
      ok = id[r] >= 0 && id[r] < 1000 && !seen[id[r]]++;
      ok = ok && x[3 * r] == all[id[r]].x.x && x[3 * r + 1] == all[id[r]].x.y && x[3 * r + 2] == all[id[r]].x.z;
    }
    std::ifstream f(dir + "/particles.xmf");
    std::stringstream ss;
    ss << f.rdbuf();
    xmf = ss.str();
  }
  CHECK(ok);
  if (rank == 0) {
    CHECK(xmf.find("TopologyType=\"Polyvertex\" NumberOfElements=\"1000\"") != std::string::npos);
    CHECK(xmf.find(">particles_000007.h5:/position<") != std::string::npos);
    CHECK(xmf.find("Name=\"radius\"") != std::string::npos);
    CHECK(xmf.find("Name=\"velocity\" AttributeType=\"Vector\"") != std::string::npos);
    CHECK(xmf.find("<Time Value=\"1.0000000000000001e-05\"/>") != std::string::npos);
    CHECK(xmf.find("HyperSlab") == std::string::npos);
    CHECK(xmf.find(dir) == std::string::npos);  // relative paths
    for (const char* f : {"/particles_000000.h5", "/particles_000007.h5", "/particles.xmf"}) std::remove((dir + f).c_str());
    rmdir(dir.c_str());
  }
}
