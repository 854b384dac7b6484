#include "vp/particles/ParticleConfig.hpp"
#include "vp/interactions/ContactOptions.hpp"
#include "vp/interactions/LubricationOptions.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <petscsys.h>
#include <sstream>

namespace vp {

namespace {

[[noreturn]] void fail(const std::string& option, const std::string& what) { failOption(option, what); }

std::string str(double v) { return formatNumber(v); }

void requireCount(PetscInt got, PetscInt want, PetscBool set, const char* option, const char* form)
{
  if (set && got != want)
    fail(option, "needs " + std::to_string(want) + " comma-separated values (" + form + "), got " + std::to_string(got));
}

struct Raw {
  char file[PETSC_MAX_PATH_LEN];
  char track[4096];
};

PetscErrorCode registerOptions(MPI_Comm comm, ParticleConfig& c, Raw& raw)
{
  PetscBool set;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Particles: input", "vpsolve");
  {
    auto vec3Option = [&](const char* name, const char* help, Vec3& v, PetscBool* wasSet) -> PetscErrorCode {
      PetscReal a[3] = {v.x, v.y, v.z};
      PetscInt count = 3;
      PetscFunctionBeginUser;
      PetscCall(PetscOptionsRealArray(name, help, "", a, &count, wasSet));
      requireCount(count, 3, *wasSet, name, "x,y,z");
      v = {a[0], a[1], a[2]};
      PetscFunctionReturn(0);
    };
    raw.file[0] = 0;
    PetscCall(PetscOptionsString("-particles_file", "Particle file: CSV with header id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz, or HDF5 (.h5) with one 1-D dataset per column", "", raw.file, raw.file, sizeof raw.file, nullptr));
    PetscReal lat[10] = {0};
    n = 10;
    PetscCall(PetscOptionsRealArray("-particles_lattice", "Cubic lattice x0,y0,z0,x1,y1,z1,spacing(m),radius(m),jitter(0..1),seed", "", lat, &n, &set));
    requireCount(n, 10, set, "-particles_lattice", "x0,y0,z0,x1,y1,z1,spacing,radius,jitter,seed");
    if (set) {
      c.lattice.set = true;
      c.lattice.lo = {lat[0], lat[1], lat[2]};
      c.lattice.hi = {lat[3], lat[4], lat[5]};
      c.lattice.spacing = lat[6];
      c.lattice.radius = lat[7];
      c.lattice.jitter = lat[8];
      if (!(lat[9] >= 0) || lat[9] != std::floor(lat[9])) fail("-particles_lattice", "seed must be an integer >= 0, got " + str(lat[9]));
      c.lattice.seed = static_cast<std::uint64_t>(lat[9]);
    }
    PetscReal rnd[9] = {0};
    n = 9;
    PetscCall(PetscOptionsRealArray("-particles_random", "Random packing x0,y0,z0,x1,y1,z1,volume_fraction,radius(m),seed", "", rnd, &n, &set));
    requireCount(n, 9, set, "-particles_random", "x0,y0,z0,x1,y1,z1,volume_fraction,radius,seed");
    if (set) {
      c.random.set = true;
      c.random.lo = {rnd[0], rnd[1], rnd[2]};
      c.random.hi = {rnd[3], rnd[4], rnd[5]};
      c.random.volumeFraction = rnd[6];
      c.random.radius = rnd[7];
      if (!(rnd[8] >= 0) || rnd[8] != std::floor(rnd[8])) fail("-particles_random", "seed must be an integer >= 0, got " + str(rnd[8]));
      c.random.seed = static_cast<std::uint64_t>(rnd[8]);
    }
    PetscCall(vec3Option("-particle_position", "One particle at x,y,z (m)", c.single.position, &set));
    c.single.set = set;
    PetscCall(vec3Option("-particle_velocity", "Its velocity (m/s)", c.single.velocity, &set));
    PetscCall(vec3Option("-particle_angular_velocity", "Its angular velocity (rad/s)", c.single.angularVelocity, &set));
    PetscBool fixed = PETSC_FALSE;
    PetscCall(PetscOptionsBool("-particle_fixed", "Infinite mass: the particle keeps its given velocity and angular velocity, a prescribed motion (held in place without them)", "", fixed, &fixed, nullptr));
    c.single.fixed = fixed;
    PetscBool all = PETSC_FALSE;
    PetscCall(PetscOptionsBool("-particles_fixed", "Every particle of infinite mass: held in place, or moving at its given constant velocity (forces still measured)", "", all, &all, nullptr));
    c.allFixed = all;
    PetscCall(PetscOptionsReal("-particle_radius", "Radius of the single particle and of generated ones (m)", "", c.radius, &c.radius, nullptr));
    PetscCall(PetscOptionsReal("-particle_density", "Density of the single particle and of generated ones (kg/m^3)", "", c.density, &c.density, nullptr));
    PetscCall(PetscOptionsReal("-particles_max_overlap", "Largest overlap accepted in the initial particles (fraction of the mean diameter; settled packings overlap slightly)", "", c.maxOverlap, &c.maxOverlap, nullptr));
    raw.track[0] = 0;
    PetscCall(PetscOptionsString("-track_particles", "Write particle_<id>.csv for these particles: all or id,id,...", "", raw.track, raw.track, sizeof raw.track, nullptr));
  }
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "DEM time integration", "vpsolve");
  {
    PetscInt m = c.substeps;
    PetscCall(PetscOptionsInt("-dem_substeps", "DEM sub-steps per fluid step", "", m, &m, nullptr));
    c.substeps = m;
    PetscCall(PetscOptionsReal("-dem_skin", "Neighbour-list skin, fraction of the largest diameter", "", c.skin, &c.skin, nullptr));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

void parseTrack(const std::string& s, ParticleConfig& c)
{
  if (s.empty()) return;
  if (s == "all") {
    c.trackAll = true;
    return;
  }
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    long long v = std::strtoll(item.c_str(), &end, 10);
    if (item.empty() || *end != 0 || v < 0) fail("-track_particles", "expected all or a comma-separated list of ids >= 0, got '" + s + "'");
    c.track.push_back(v);
  }
}

} // namespace

ParticleConfig ParticleConfig::fromOptions(MPI_Comm comm)
{
  ParticleConfig c;
  Raw raw{};
  VP_CALL(registerOptions(comm, c, raw));
  c.file = raw.file;
  parseTrack(raw.track, c);
  c.contact = readContactOptions(comm);
  c.lubrication = readLubricationOptions(comm);
  c.validate();
  return c;
}

void ParticleConfig::validate() const
{
  auto positive = [](double v, const char* opt) {
    if (!(v > 0) || !std::isfinite(v)) fail(opt, "must be > 0, got " + str(v));
  };
  int sources = !file.empty() + lattice.set + random.set + single.set;
  if (sources > 1) fail("-particles_file", "give only one of -particles_file, -particles_lattice, -particles_random, -particle_position");
  positive(radius, "-particle_radius");
  positive(density, "-particle_density");
  if (lattice.set) {
    positive(lattice.spacing, "-particles_lattice");
    positive(lattice.radius, "-particles_lattice");
    if (2 * lattice.radius > lattice.spacing) fail("-particles_lattice", "spacing " + str(lattice.spacing) + " must be >= the diameter " + str(2 * lattice.radius));
    if (!(lattice.jitter >= 0 && lattice.jitter <= 1)) fail("-particles_lattice", "jitter must be in [0, 1], got " + str(lattice.jitter));
    for (int d = 0; d < 3; ++d)
      if (!(lattice.hi[d] > lattice.lo[d])) fail("-particles_lattice", "box upper corner must exceed its lower corner");
  }
  if (random.set) {
    positive(random.radius, "-particles_random");
    if (!(random.volumeFraction > 0 && random.volumeFraction <= 0.35))
      fail("-particles_random", "volume fraction must be in (0, 0.35] (random sequential addition), got " + str(random.volumeFraction));
    for (int d = 0; d < 3; ++d)
      if (!(random.hi[d] - random.lo[d] > 2 * random.radius)) fail("-particles_random", "box must be wider than a particle diameter along every axis");
  }
  if (!(maxOverlap >= 0 && maxOverlap < 0.5)) fail("-particles_max_overlap", "must be in [0, 0.5), got " + str(maxOverlap));
  contact.validate(any());
  if (substeps < 1) fail("-dem_substeps", "must be >= 1, got " + std::to_string(substeps));
  if (!(skin > 0 && skin <= 1)) fail("-dem_skin", "must be in (0, 1], got " + str(skin));
}

} // namespace vp
