#include "vp/io/Diagnostics.hpp"

namespace vp {

Diagnostics::Diagnostics(MPI_Comm comm, const std::string& dir, bool particles, double resumeStep)
{
  std::vector<std::string> columns{"step", "time", "dt", "cfl", "pressure_iterations", "max_divergence",
                                   "kinetic_energy", "wall_time", "velocity_iterations", "mean_u", "mean_v", "mean_w"};
  if (particles)
    for (const char* c : {"particle_kinetic_energy", "contacts", "wall_contacts"}) columns.push_back(c);
  csv_ = std::make_unique<CsvWriter>(comm, dir + "/diagnostics.csv", columns, resumeStep);
}

void Diagnostics::record(int step, double time, double dt, const StepStats& solvers, const ops::FieldStats& s, double rho,
                         double wallTime, const DemSolver* dem)
{
  std::vector<double> row{double(step), time, dt, dt * s.maxRate, double(solvers.pressureIterations), s.maxDivergence,
                          rho * s.kineticEnergy, wallTime, double(solvers.velocityIterations),
                          s.meanVelocity.x, s.meanVelocity.y, s.meanVelocity.z};
  if (dem) {
    const DemDiagnostics d = dem->diagnostics();
    row.insert(row.end(), {d.kineticEnergy, double(d.contacts), double(d.wallContacts)});
  }
  csv_->row(row);
}

} // namespace vp
