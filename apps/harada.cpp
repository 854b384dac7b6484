// harada: point-particle reference model of a sphere moving normal to a wall (Harada et al. 2001;
// docs/lubrication.md). Writes particle_0.csv (the vpsolve particle columns plus the force terms)
// into -output_dir. The wall is the plane y = 0; gravity and motion are along y.
#include "vp/core/Error.hpp"
#include "vp/interactions/Harada.hpp"
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
  double position[3] = {0, 0.2159, 0};
  double velocity[3] = {0, 0, 0};
  double gravity[3] = {0, -9.781, 0};
  double timeFinal = 3;
  char outputDir[PETSC_MAX_PATH_LEN] = "output";
  PetscInt outputEvery = 10;
};

std::string str(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

[[noreturn]] void fail(const std::string& option, const std::string& what)
{
  throw InputError("option " + option + ": " + what);
}

void vector3(PetscInt n, PetscBool set, const char* option)
{
  if (set && n != 3) fail(option, "needs 3 comma-separated values, got " + std::to_string(n));
}

PetscErrorCode registerOptions(Run& r)
{
  HaradaParams& m = r.model;
  PetscInt n;
  PetscBool set, flag;
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "Harada point-particle model (defaults: the seed falling sphere)", "harada");
  PetscCall(PetscOptionsReal("-fluid_rho", "Fluid density (kg/m^3)", "", m.fluidDensity, &m.fluidDensity, nullptr));
  PetscCall(PetscOptionsReal("-fluid_mu", "Fluid dynamic viscosity (Pa s)", "", m.viscosity, &m.viscosity, nullptr));
  PetscCall(PetscOptionsReal("-particle_radius", "Sphere radius a (m)", "", m.radius, &m.radius, nullptr));
  PetscCall(PetscOptionsReal("-particle_density", "Sphere density (kg/m^3)", "", m.particleDensity, &m.particleDensity, nullptr));
  n = 3;
  PetscCall(PetscOptionsRealArray("-particle_position", "Initial centre x,y,z (m), default 0,0.2159,0; y is the height above the wall", "", r.position, &n, &set));
  vector3(n, set, "-particle_position");
  n = 3;
  PetscCall(PetscOptionsRealArray("-particle_velocity", "Initial velocity 0,vy,0 (m/s), default 0,0,0", "", r.velocity, &n, &set));
  vector3(n, set, "-particle_velocity");
  n = 3;
  PetscCall(PetscOptionsRealArray("-gravity", "Gravity 0,gy,0 (m/s^2) normal to the wall, default 0,-9.781,0", "", r.gravity, &n, &set));
  vector3(n, set, "-gravity");
  PetscCall(PetscOptionsReal("-contact_restitution", "Dry normal restitution xi_n in (0, 1]", "", m.restitution, &m.restitution, nullptr));
  PetscCall(PetscOptionsReal("-contact_tc", "Contact duration t_c (s)", "", m.contactTime, &m.contactTime, nullptr));
  PetscCall(PetscOptionsReal("-contact_roughness", "Roughness gap as a fraction of the diameter; lubrication and image series are held below it", "", m.roughness, &m.roughness, nullptr));
  const struct { const char* name; const char* text; bool* value; } terms[] = {
    {"-harada_drag", "Schiller-Naumann steady drag", &m.drag},
    {"-harada_lubrication", "Lubrication force 6 pi mu a U / eps", &m.lubrication},
    {"-harada_added_mass", "Added mass", &m.addedMass},
    {"-harada_image_series", "Wall (image series) correction of the added mass", &m.imageSeries},
    {"-harada_history", "Basset history force", &m.history},
    {"-harada_contact", "Spring-dashpot contact with the wall", &m.contact},
  };
  for (const auto& t : terms) {
    flag = *t.value ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(PetscOptionsBool(t.name, t.text, "", flag, &flag, nullptr));
    *t.value = flag;
  }
  PetscCall(PetscOptionsReal("-time_dt", "Time step (s); at most t_c/30 with contact", "", m.dt, &m.dt, nullptr));
  PetscCall(PetscOptionsReal("-time_final", "End time (s)", "", r.timeFinal, &r.timeFinal, nullptr));
  PetscCall(PetscOptionsString("-output_dir", "Directory for particle_0.csv", "", r.outputDir, r.outputDir, sizeof r.outputDir, nullptr));
  PetscCall(PetscOptionsInt("-output_every", "Steps between rows of particle_0.csv (>= 1)", "", r.outputEvery, &r.outputEvery, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

void validate(Run& r)
{
  HaradaParams& m = r.model;
  auto positive = [](const char* option, double v) {
    if (!(v > 0) || !std::isfinite(v)) fail(option, "must be > 0, got " + str(v));
  };
  positive("-fluid_rho", m.fluidDensity);
  positive("-fluid_mu", m.viscosity);
  positive("-particle_radius", m.radius);
  positive("-particle_density", m.particleDensity);
  positive("-contact_tc", m.contactTime);
  positive("-time_dt", m.dt);
  positive("-time_final", r.timeFinal);
  if (!(m.restitution > 0 && m.restitution <= 1)) fail("-contact_restitution", "must be in (0, 1], got " + str(m.restitution));
  if (!(m.roughness > 0 && m.roughness < 0.5)) fail("-contact_roughness", "must be in (0, 0.5) (fraction of the diameter), got " + str(m.roughness));
  if (r.velocity[0] != 0 || r.velocity[2] != 0) fail("-particle_velocity", "the model moves normal to the wall only: x and z must be 0");
  if (r.gravity[0] != 0 || r.gravity[2] != 0) fail("-gravity", "the model moves normal to the wall only: x and z must be 0");
  m.gravity = r.gravity[1];
  const double hCol = 2 * m.radius * m.roughness;
  if (!(r.position[1] - m.radius > hCol))
    fail("-particle_position", "y must exceed radius + roughness gap = " + str(m.radius + hCol) + ", got " + str(r.position[1]));
  if (m.contact && m.dt > m.contactTime / 30)
    fail("-time_dt", "must be <= -contact_tc / 30 = " + str(m.contactTime / 30) + " to resolve the contact, got " + str(m.dt));
  if (r.outputEvery < 1) fail("-output_every", "must be >= 1, got " + std::to_string(r.outputEvery));
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
  Run r;
  VP_CALL(registerOptions(r));
  PetscBool helpOnly = PETSC_FALSE;
  VP_CALL(PetscOptionsHasHelp(nullptr, &helpOnly));
  if (helpOnly) return 0;
  validate(r);

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
