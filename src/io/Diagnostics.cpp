#include "vp/io/Diagnostics.hpp"

namespace vp {

Diagnostics::Diagnostics(MPI_Comm comm, const std::string& dir, bool particles, double rho, double resumeStep) : rho_(rho)
{
  std::vector<std::string> columns{"step", "time", "dt", "cfl", "pressure_iterations", "max_divergence",
                                   "kinetic_energy", "wall_time", "velocity_iterations", "mean_u", "mean_v", "mean_w"};
  if (particles)
    for (const char* c : {"particle_kinetic_energy", "contacts", "wall_contacts"}) columns.push_back(c);
  csv_ = std::make_unique<CsvWriter>(comm, dir + "/diagnostics.csv", columns, resumeStep);
}

void Diagnostics::record(const RunView& run)
{
  const ops::FieldStats& s = run.fluid->stats();
  const double dt = run.fluid->previousDt();
  std::vector<double> row{double(run.step), run.time, dt, dt * s.maxRate, double(run.solvers->pressureIterations), s.maxDivergence,
                          rho_ * s.kineticEnergy, run.wallTime, double(run.solvers->velocityIterations),
                          s.meanVelocity.x, s.meanVelocity.y, s.meanVelocity.z};
  if (run.dem) {
    const DemDiagnostics d = run.dem->diagnostics();
    row.insert(row.end(), {d.kineticEnergy, double(d.contacts), double(d.wallContacts)});
  }
  csv_->row(row);
}

} // namespace vp
