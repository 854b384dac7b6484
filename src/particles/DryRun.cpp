#include "vp/particles/DryRun.hpp"
#include "vp/core/Error.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/io/ParticleTracker.hpp"
#include "vp/io/ParticleWriter.hpp"
#include "vp/particles/DemSolver.hpp"
#include <cmath>
#include <cstdio>
#include <sys/stat.h>

namespace vp {

long runDryDem(MPI_Comm comm, const Config& c, const ParticleConfig& pc)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  if (!pc.any()) throw InputError("option -fluid_off: a DEM-only run needs particles (-particles_file, -particles_lattice, -particles_random or -particle_position)");
  Grid grid(comm, c.grid, c.bc);
  DemSolver dem(grid, c, pc);
  // With -fluid_off the step is the DEM step times the sub-steps.
  const double dt = c.time.dt > 0 ? c.time.dt : dem.suggestedStep() * pc.substeps;
  if (rank == 0) mkdir(c.output.dir.c_str(), 0755);
  MPI_Barrier(comm);
  ParticleWriter writer(comm, c.output.dir);
  ParticleTracker tracker(comm, c.output.dir, pc, dem.particles());
  FILE* diag = nullptr;
  if (rank == 0) {
    diag = std::fopen((c.output.dir + "/diagnostics.csv").c_str(), "w");
    if (!diag) throw InputError("option -output_dir: cannot write to '" + c.output.dir + "'");
    std::fprintf(diag, "step,time,dt,cfl,pressure_iterations,max_divergence,kinetic_energy,wall_time,"
                       "particle_kinetic_energy,contacts,wall_contacts\n");
  }
  auto snapshotDue = [&](long step, double t, double tPrev) {
    if (c.output.every > 0 && step % c.output.every == 0) return true;
    return c.output.dt > 0 && std::floor(t / c.output.dt + 1e-9) > std::floor(tPrev / c.output.dt + 1e-9);
  };
  double t = 0;
  long step = 0;
  if (c.output.every > 0 || c.output.dt > 0) writer.write(dem.particles(), 0, 0);
  tracker.record(dem.particles(), 0);
  const double start = MPI_Wtime();
  while (step < c.time.maxSteps && t < c.time.final * (1 - 1e-12)) {
    const double tPrev = t;
    dem.advance(t, dt);
    ++step;
    t = step * dt;
    const DemDiagnostics d = dem.diagnostics();
    const double wall = MPI_Wtime() - start;
    if (diag)
      std::fprintf(diag, "%ld,%.10g,%.6g,0,0,0,0,%.4f,%.10g,%ld,%ld\n", step, t, dt, wall, d.kineticEnergy, d.contacts,
                   d.wallContacts);
    tracker.record(dem.particles(), t);
    if (snapshotDue(step, t, tPrev)) writer.write(dem.particles(), static_cast<int>(step), t);
    if (rank == 0 && c.output.monitorEvery > 0 && step % c.output.monitorEvery == 0)
      std::printf("step %ld  t %.6g  particle KE %.6g J  contacts %ld  wall contacts %ld  wall time %.2f s\n", step, t,
                  d.kineticEnergy, d.contacts, d.wallContacts, wall);
  }
  const double loop = MPI_Wtime() - start;
  tracker.flush();
  if (diag) std::fclose(diag);
  const DemDiagnostics d = dem.diagnostics();
  if (rank == 0)
    std::printf("DEM loop: %ld particles, %ld steps x %d sub-steps, loop time %.3f s, %.4g particle-steps/s, "
                "%zu list rebuilds\n",
                d.particles, step, pc.substeps, loop, d.particles * double(step) * pc.substeps / loop, dem.rebuilds());
  return step;
}

} // namespace vp
