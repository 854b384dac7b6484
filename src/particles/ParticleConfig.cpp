#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/Shape.hpp"
#include "vp/interactions/ContactOptions.hpp"
#include "vp/interactions/LubricationOptions.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace vp {

namespace {

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
    if ((item.empty() || *end != 0 || v < 0) && !optionsHelpMode()) failOption("-track_particles", "expected all or a comma-separated list of ids >= 0, got '" + s + "'");
    c.track.push_back(v);
  }
}

std::uint64_t seed(double v, const char* option)
{
  if (!optionsHelpMode() && (!(v >= 0) || v != std::floor(v))) failOption(option, "seed must be an integer >= 0, got " + formatNumber(v));
  return static_cast<std::uint64_t>(v);
}

} // namespace

ParticleConfig ParticleConfig::read()
{
  ParticleConfig c;
  {
    OptionGroup o("Particles: input");
    c.file = o.text("-particles_file", "", "Particle file: CSV with header id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz, "
                                           "or HDF5 (.h5) with one 1-D dataset per column");
    const std::vector<double> lat = o.reals("-particles_lattice", 10, "x0,y0,z0,x1,y1,z1,spacing,radius,jitter,seed",
                                            "Cubic lattice x0,y0,z0,x1,y1,z1,spacing(m),radius(m),jitter(0..1),seed");
    if (!lat.empty()) {
      c.lattice.set = true;
      c.lattice.lo = {lat[0], lat[1], lat[2]};
      c.lattice.hi = {lat[3], lat[4], lat[5]};
      c.lattice.spacing = lat[6];
      c.lattice.radius = lat[7];
      c.lattice.jitter = lat[8];
      c.lattice.seed = seed(lat[9], "-particles_lattice");
    }
    // x0,y0,z0,x1,y1,z1,volume_fraction,radius,seed
    auto boxFraction = [&](const char* name, const char* help, RandomInput& in) {
      const std::vector<double> v = o.reals(name, 9, "x0,y0,z0,x1,y1,z1,volume_fraction,radius,seed", help);
      if (v.empty()) return;
      in.set = true;
      in.lo = {v[0], v[1], v[2]};
      in.hi = {v[3], v[4], v[5]};
      in.volumeFraction = v[6];
      in.radius = v[7];
      in.seed = seed(v[8], name);
    };
    boxFraction("-particles_random", "Random packing x0,y0,z0,x1,y1,z1,volume_fraction,radius(m),seed", c.random);
    c.random.radiusSpread = o.real("-particles_radius_spread", 0, "With -particles_random: radii uniform in "
                                                                 "radius (1 - s) .. radius (1 + s) (0: monodisperse)");
    boxFraction("-particles_packed", "Dense random packing without overlaps, grown in the box x0,y0,z0,x1,y1,z1 to "
                                     "volume_fraction (up to about 0.6), radius(m), seed", c.packed);
    c.packed.sizeRatio = o.real("-particles_size_ratio", 1, "With -particles_packed: 1 monodisperse; > 1 bidisperse, equal "
                                                            "volumes of spheres of the radius and of this times the radius");
    c.single.position = o.vec3("-particle_position", {}, "One particle at x,y,z (m)", &c.single.set);
    c.single.velocity = o.vec3("-particle_velocity", {}, "Its velocity (m/s)");
    c.single.angularVelocity = o.vec3("-particle_angular_velocity", {}, "Its angular velocity (rad/s)");
    c.single.fixed = o.flag("-particle_fixed", false, "Infinite mass: the particle keeps its given velocity and angular velocity, "
                                                      "a prescribed motion (held in place without them)");
    c.allFixed = o.flag("-particles_fixed", false, "Every particle of infinite mass: held in place, or moving at its given "
                                                   "constant velocity (forces still measured)");
    c.roughWalls = o.real("-particles_rough_walls", 0, "Rough walls (a shear cell's): a square layer of fixed spheres of this "
                                                      "radius (m) touching each z wall, at least 2.1 radii apart, moving with the "
                                                      "wall (-bc_z*_velocity); beside the other particles (give them room); 0: none");
    c.radius = o.real("-particle_radius", c.radius, "Radius of the single particle and of generated ones (m)");
    c.density = o.real("-particle_density", c.density, "Density of the single particle and of generated ones (kg/m^3)");
    c.spheroid = o.choice("-particle_shape", {"sphere", "spheroid"}, 0,
                          "Shape of the single particle, a lattice's or random ones: sphere or spheroid (equatorial "
                          "semi-axis the given radius, polar -particle_aspect times it; docs/shapes.md)") == 1;
    c.aspect = o.real("-particle_aspect", c.aspect, "Spheroid: polar over equatorial semi-axis c/a (> 1 prolate, < 1 oblate)");
    c.axis = o.vec3("-particle_axis", c.axis, "Spheroid: initial direction x,y,z of its symmetry axis");
    c.randomAxes = o.choice("-particle_orientation", {"aligned", "random"}, 0,
                            "Generated spheroids: every axis along -particle_axis, or uniform on the sphere (from the "
                            "generator's seed)") == 1;
  }
  {
    // Checks and outputs, not the set-up: a restart may change them.
    OptionGroup o("Particles: input checks and tracking", false);
    c.maxOverlap = o.real("-particles_max_overlap", c.maxOverlap, "Largest overlap accepted in the initial particles "
                                                                  "(fraction of the mean diameter; settled packings overlap slightly)");
    parseTrack(o.text("-track_particles", "", "Write particle_<id>.csv for these particles: all or id,id,..."), c);
  }
  {
    // The sub-steps change the numerics, not the set-up: a restart may raise them.
    OptionGroup o("DEM time integration", false);
    c.substeps = o.integer("-dem_substeps", c.substeps, "DEM sub-steps per fluid step");
    c.skin = o.real("-dem_skin", c.skin, "Neighbour-list skin, fraction of the largest diameter");
    c.implicitDrag = o.real("-dem_implicit_drag", c.implicitDrag,
                            "Fraction k of the Stokes resistance (6 pi mu a, 8 pi mu a^3) by which the resolved force and "
                            "torque follow the particle's own velocity change within a fluid step, implicit in the sub-steps: "
                            "keeps the coupling stable when the fluid step exceeds the particle's viscous relaxation time "
                            "(spin: rho_p d^2 / (60 mu)); 0: held fixed (docs/coupling.md)");
    c.orientation = o.flag("-dem_orientation", c.orientation,
                           "Integrate each sphere's orientation (the quaternion of snapshots and checkpoints); false: "
                           "orientations keep their initial values (no force on a sphere depends on them; about a tenth "
                           "of a dry DEM step)");
  }
  {
    OptionGroup o("DEM-only liquid");
    c.dragViscosity = o.real("-dem_drag_viscosity", c.dragViscosity,
                             "Viscosity (Pa s) of a still liquid acting on each particle alone by Stokes drag -3 pi mu d v and "
                             "torque -pi mu d^3 w, without buoyancy or interactions (preparing packings by sedimentation, "
                             "-fluid_off only; 0: none)");
  }
  c.contact = readContactOptions();
  c.lubrication = readLubricationOptions();
  return c;
}

void ParticleConfig::resolveDefaults(const Config& main)
{
  const double cell = std::min({main.grid.spacing(0), main.grid.spacing(1), main.grid.spacing(2)});
  lubrication.resolveDefaults(cell, !main.fluid.off, 2 * contact.roughness);
}

void ParticleConfig::validate() const
{
  auto positive = [](double v, const char* opt) {
    if (!(v > 0) || !std::isfinite(v)) failOption(opt, "must be > 0, got " + formatNumber(v));
  };
  // Up to the hindered-settling resistance of dense packings (tens of times Stokes).
  if (!(implicitDrag >= 0 && implicitDrag <= 100)) failOption("-dem_implicit_drag", "must be in [0, 100]", implicitDrag);
  int sources = !file.empty() + lattice.set + random.set + packed.set + single.set;
  if (sources > 1)
    failOption("-particles_file", "give only one of -particles_file, -particles_lattice, -particles_random, -particles_packed, -particle_position");
  if (!(roughWalls >= 0) || !std::isfinite(roughWalls)) failOption("-particles_rough_walls", "must be >= 0 (m; 0: none), got " + formatNumber(roughWalls));
  positive(radius, "-particle_radius");
  positive(density, "-particle_density");
  if (lattice.set) {
    positive(lattice.spacing, "-particles_lattice");
    positive(lattice.radius, "-particles_lattice");
    if (2 * lattice.radius > lattice.spacing) failOption("-particles_lattice", "spacing " + formatNumber(lattice.spacing) + " must be >= the diameter " + formatNumber(2 * lattice.radius));
    if (!(lattice.jitter >= 0 && lattice.jitter <= 1)) failOption("-particles_lattice", "jitter must be in [0, 1], got " + formatNumber(lattice.jitter));
    for (int d = 0; d < 3; ++d)
      if (!(lattice.hi[d] > lattice.lo[d])) failOption("-particles_lattice", "box upper corner must exceed its lower corner");
  }
  if (!(random.radiusSpread >= 0 && random.radiusSpread <= 0.5))
    failOption("-particles_radius_spread", "must be in [0, 0.5] (0: monodisperse), got " + formatNumber(random.radiusSpread));
  if (random.radiusSpread != 0 && !random.set) failOption("-particles_radius_spread", "applies to -particles_random only");
  if (random.set) {
    positive(random.radius, "-particles_random");
    if (!(random.volumeFraction > 0 && random.volumeFraction <= 0.35))
      failOption("-particles_random", "volume fraction must be in (0, 0.35] (random sequential addition), got " + formatNumber(random.volumeFraction));
    for (int d = 0; d < 3; ++d)
      if (!(random.hi[d] - random.lo[d] > 2 * random.radius * (1 + random.radiusSpread)))
        failOption("-particles_random", "box must be wider than the largest particle diameter along every axis");
  }
  if (packed.set) {
    positive(packed.radius, "-particles_packed");
    if (!(packed.volumeFraction > 0 && packed.volumeFraction <= 0.6))
      failOption("-particles_packed", "volume fraction must be in (0, 0.6] (a random packing jams near 0.64), got " +
                                          formatNumber(packed.volumeFraction));
    for (int d = 0; d < 3; ++d)
      if (!(packed.hi[d] - packed.lo[d] > 2 * packed.radius * packed.sizeRatio))
        failOption("-particles_packed", "box must be wider than the largest particle diameter along every axis");
  }
  if (!(packed.sizeRatio >= 1 && packed.sizeRatio <= 4))
    failOption("-particles_size_ratio", "must be in [1, 4] (1: monodisperse), got " + formatNumber(packed.sizeRatio));
  if (packed.sizeRatio != 1 && !packed.set) failOption("-particles_size_ratio", "applies to -particles_packed only");
  if (spheroid) {
    if (!(aspect > 0) || !std::isfinite(aspect)) failOption("-particle_aspect", "must be > 0 (c/a: > 1 prolate, < 1 oblate), got " + formatNumber(aspect));
    if (!(norm(axis) > 0) || !std::isfinite(norm(axis))) failOption("-particle_axis", "must be a non-zero direction x,y,z");
    if (!single.set && !lattice.set && !random.set)
      failOption("-particle_shape", "spheroid applies to the single particle (-particle_position), a lattice or random particles; "
                                    "a file gives shapes in its aspect and qw,qx,qy,qz columns, and -particles_packed grows spheres");
    const double bound = Shape{1.0, aspect}.boundingRadius();  // over the equatorial semi-axis
    if (lattice.set && 2 * bound * lattice.radius > lattice.spacing)
      failOption("-particles_lattice", "spacing " + formatNumber(lattice.spacing) + " must be >= the spheroids' longest axis " +
                                           formatNumber(2 * bound * lattice.radius));
    // Random addition excludes the bounding spheres: their volume fraction is the spheroids' times bound^3 / aspect.
    if (random.set && random.volumeFraction * bound * bound * bound / aspect > 0.35)
      failOption("-particles_random", "the spheroids' bounding spheres would fill " +
                                          formatNumber(random.volumeFraction * bound * bound * bound / aspect) +
                                          " of the box, more than random sequential addition reaches (0.35): at most " +
                                          formatNumber(0.35 * aspect / (bound * bound * bound)) + " for aspect " + formatNumber(aspect));
  } else if (aspect != 1 || !(axis.x == 0 && axis.y == 0 && axis.z == 1) || randomAxes) {
    failOption(aspect != 1 ? "-particle_aspect" : randomAxes ? "-particle_orientation" : "-particle_axis", "needs -particle_shape spheroid");
  }
  if (randomAxes && single.set) failOption("-particle_orientation", "random is for generated spheroids; give -particle_axis");
  if (!(maxOverlap >= 0 && maxOverlap < 0.5)) failOption("-particles_max_overlap", "must be in [0, 0.5), got " + formatNumber(maxOverlap));
  contact.validate();
  if (contact.departureCells > 0 && lubrication.model == LubModel::None)
    failOption("-contact_hydro_departure", "needs -lub_model blcm or llcm (the correction stands for the film there)");
  if (substeps < 1) failOption("-dem_substeps", "must be >= 1, got " + std::to_string(substeps));
  if (!(skin > 0 && skin <= 1)) failOption("-dem_skin", "must be in (0, 1], got " + formatNumber(skin));
}

} // namespace vp
