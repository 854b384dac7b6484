// harada: point-particle reference model of a sphere moving normal to a wall (Harada et al. 2001;
// docs/lubrication.md). Writes particle_0.csv (the vpsolve particle columns plus the force terms)
// into -output_dir. The wall is the plane y = 0; gravity and motion are along y.
#include "vp/RunConfig.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "harada/Harada.hpp"
#include <petscsys.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

using namespace vp;

static const char help[] =
  "harada: sphere moving normal to the wall y = 0 with drag, lubrication, image-series added mass,\n"
  "Basset history and spring-dashpot contact (Harada et al. 2001). Writes <output_dir>/particle_0.csv.\n";

namespace {

struct Run {
  HaradaParams model;
  Vec3 position{0, 0.2159, 0};
  Vec3 velocity{0, 0, 0};
  Vec3 gravity{0, -9.781, 0};
  double timeFinal = 3;
  std::string outputDir = "output";
  int outputEvery = 10;
};

Run readOptions()
{
  Run r;
  HaradaParams& m = r.model;
  OptionGroup o("Harada point-particle model (defaults: the seed falling sphere)");
  m.fluidDensity = o.real("-fluid_rho", m.fluidDensity, "Fluid density (kg/m^3)");
  m.viscosity = o.real("-fluid_mu", m.viscosity, "Fluid dynamic viscosity (Pa s)");
  m.radius = o.real("-particle_radius", m.radius, "Sphere radius a (m)");
  m.particleDensity = o.real("-particle_density", m.particleDensity, "Sphere density (kg/m^3)");
  r.position = o.vec3("-particle_position", r.position, "Initial centre x,y,z (m); y is the height above the wall");
  r.velocity = o.vec3("-particle_velocity", r.velocity, "Initial velocity 0,vy,0 (m/s)");
  r.gravity = o.vec3("-gravity", r.gravity, "Gravity 0,gy,0 (m/s^2) normal to the wall");
  m.restitution = o.real("-contact_restitution", m.restitution, "Dry normal restitution xi_n in (0, 1]");
  m.contactTime = o.real("-contact_tc", m.contactTime, "Contact duration t_c (s)");
  m.roughness = o.real("-contact_roughness", m.roughness, "Roughness gap as a fraction of the diameter; lubrication and image "
                                                          "series are held below it");
  m.drag = o.flag("-harada_drag", m.drag, "Schiller-Naumann steady drag");
  m.lubrication = o.flag("-harada_lubrication", m.lubrication, "Lubrication force 6 pi mu a U / eps");
  m.addedMass = o.flag("-harada_added_mass", m.addedMass, "Added mass");
  m.imageSeries = o.flag("-harada_image_series", m.imageSeries, "Wall (image series) correction of the added mass");
  m.history = o.flag("-harada_history", m.history, "Basset history force");
  m.historyWindow = o.real("-harada_history_window", m.historyWindow,
                           "Gap (m) up to which the history force is left out from a contact on the way out, or until the "
                           "sphere turns back (below the roughness gap: during the contact only; 0: never)");
  m.contact = o.flag("-harada_contact", m.contact, "Spring-dashpot contact with the wall");
  m.dt = o.real("-time_dt", m.dt, "Time step (s); at most t_c/30 with contact");
  r.timeFinal = o.real("-time_final", r.timeFinal, "End time (s)");
  r.outputDir = o.text("-output_dir", r.outputDir, "Directory for particle_0.csv");
  r.outputEvery = o.integer("-output_every", r.outputEvery, "Steps between rows of particle_0.csv (>= 1)");
  return r;
}

void validate(Run& r)
{
  HaradaParams& m = r.model;
  auto positive = [](const char* option, double v) {
    if (!(v > 0) || !std::isfinite(v)) failOption(option, "must be > 0, got " + formatNumber(v));
  };
  positive("-fluid_rho", m.fluidDensity);
  positive("-fluid_mu", m.viscosity);
  positive("-particle_radius", m.radius);
  positive("-particle_density", m.particleDensity);
  positive("-contact_tc", m.contactTime);
  positive("-time_dt", m.dt);
  positive("-time_final", r.timeFinal);
  if (!(m.restitution > 0 && m.restitution <= 1)) failOption("-contact_restitution", "must be in (0, 1], got " + formatNumber(m.restitution));
  if (!(m.roughness > 0 && m.roughness < 0.5)) failOption("-contact_roughness", "must be in (0, 0.5) (fraction of the diameter), got " + formatNumber(m.roughness));
  if (r.velocity[0] != 0 || r.velocity[2] != 0) failOption("-particle_velocity", "the model moves normal to the wall only: x and z must be 0");
  if (r.gravity[0] != 0 || r.gravity[2] != 0) failOption("-gravity", "the model moves normal to the wall only: x and z must be 0");
  m.gravity = r.gravity[1];
  const double hCol = 2 * m.radius * m.roughness;
  if (!(r.position[1] - m.radius > hCol))
    failOption("-particle_position", "y must exceed radius + roughness gap = " + formatNumber(m.radius + hCol) + ", got " + formatNumber(r.position[1]));
  if (m.contact && m.dt > m.contactTime / 30)
    failOption("-time_dt", "must be <= -contact_tc / 30 = " + formatNumber(m.contactTime / 30) + " to resolve the contact, got " + formatNumber(m.dt));
  if (!(m.historyWindow >= 0) || !std::isfinite(m.historyWindow))
    failOption("-harada_history_window", "must be >= 0 (m; 0: never), got " + formatNumber(m.historyWindow));
  if (m.historyWindow > 0 && !(m.history && m.contact))
    failOption("-harada_history_window", "needs -harada_history and -harada_contact (it opens at a contact)");
  if (r.outputEvery < 1) failOption("-output_every", "must be >= 1, got " + std::to_string(r.outputEvery));
}

void writeRow(std::ofstream& out, const HaradaModel& h, const Run& r)
{
  const HaradaForces& f = h.forces();
  out << h.time() << ',' << r.position[0] << ',' << h.height() << ',' << r.position[2] << ",0," << h.velocity()
      << ",0,0,0,0,0," << f.hydrodynamic() << ",0," << h.gap() << ',' << f.drag << ',' << f.lubrication << ','
      << f.addedMass << ',' << f.history << ',' << f.contact << ',' << f.weight << '\n';
}

int run()
{
  PetscBool helpOnly = PETSC_FALSE;
  VP_CALL(PetscOptionsHasHelp(nullptr, &helpOnly));
  if (helpOnly) {
    setOptionsHelpMode(true);
    readOptions();
    PetscPrintf(PETSC_COMM_WORLD, "%s", help);
    int rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    printOptionHelp(rank);
    return 0;
  }
  Run r = readOptions();
  validate(r);
  checkUnknownOptions(PETSC_COMM_WORLD, false);

  std::filesystem::create_directories(r.outputDir);
  const std::string path = std::string(r.outputDir) + "/particle_0.csv";
  std::ofstream out(path);
  if (!out) throw InputError("option -output_dir: cannot write " + path);
  out << std::setprecision(10);
  out << "time,x,y,z,vx,vy,vz,wx,wy,wz,fx,fy,fz,gap,f_drag,f_lubrication,f_added_mass,f_history,f_contact,f_weight\n";

  HaradaModel h(r.model, r.position[1], r.velocity[1]);
  writeRow(out, h, r);
  double vMin = 0, minGap = h.gap();
  long step = 0;
  while (h.time() < r.timeFinal - 0.5 * r.model.dt) {
    h.step();
    vMin = std::min(vMin, h.velocity());
    minGap = std::min(minGap, h.gap());
    if (++step % r.outputEvery == 0) writeRow(out, h, r);
  }
  const HaradaParams& m = r.model;
  const double d = 2 * m.radius;
  VP_CALL(PetscPrintf(PETSC_COMM_WORLD,
                        "harada: %ld steps to t = %g s; peak approach speed %.6g m/s (St %.3g, Re %.3g); "
                        "smallest gap %.3g d; wrote %s\n",
                        step, h.time(), -vMin, m.particleDensity * -vMin * d / (9 * m.viscosity),
                        m.fluidDensity * -vMin * d / m.viscosity, minGap / d, path.c_str()));
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, help) != 0) return 1;
  int status = 0;
  try {
    status = run();
  } catch (const InputError& e) {
    PetscPrintf(PETSC_COMM_WORLD, "harada: error: %s\n", e.what());
    status = 1;
  } catch (const std::exception& e) {
    PetscPrintf(PETSC_COMM_WORLD, "harada: failure: %s\n", e.what());
    status = 2;
  }
  PetscFinalize();
  return status;
}
