#pragma once
// Particle, contact and DEM options (-particles_*, -particle_*, -contact_*, -dem_*, -track_particles):
// read() parses them (vp/core/Options.hpp), validate() checks them; bad values raise
// vp::InputError naming the option and the valid range.
#include "vp/core/Config.hpp"
#include "vp/core/Vec3.hpp"
#include "vp/interactions/ContactConfig.hpp"
#include "vp/interactions/LubricationModel.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace vp {

// -particles_lattice x0,y0,z0,x1,y1,z1,spacing,radius,jitter,seed: simple cubic lattice in a box;
// jitter moves each centre by up to jitter * (spacing/2 - radius) per axis (never overlapping).
struct LatticeInput {
  bool set = false;
  Vec3 lo, hi;
  double spacing = 0, radius = 0, jitter = 0;
  std::uint64_t seed = 0;
};

// -particles_random x0,y0,z0,x1,y1,z1,volume_fraction,radius,seed: random sequential addition of
// non-overlapping spheres (centres inside the box, spheres inside it) up to a volume fraction;
// with -particles_radius_spread s the radii are uniform in [radius (1 - s), radius (1 + s)].
struct RandomInput {
  bool set = false;
  Vec3 lo, hi;
  double volumeFraction = 0, radius = 0;
  std::uint64_t seed = 0;
  double radiusSpread = 0;
};

// -particles_packed (the same nine values) and -particles_size_ratio (particles/Packing.hpp).
struct PackedInput : RandomInput {
  double sizeRatio = 1;   // 1 monodisperse, > 1 bidisperse
};

// One particle from -particle_position (single-sphere cases).
struct SingleInput {
  bool set = false;
  Vec3 position, velocity, angularVelocity;
  bool fixed = false;
};

struct ParticleConfig {
  std::string file;           // -particles_file: CSV (.csv) or HDF5 table (.h5)
  LatticeInput lattice;
  RandomInput random;
  PackedInput packed;
  SingleInput single;
  double radius = 1e-3;       // -particle_radius [m] (single particle, lattice/random default)
  double density = 2500;      // -particle_density [kg/m^3] (single, lattice, random)
  bool spheroid = false;      // -particle_shape spheroid (the single particle, a lattice's, random ones)
  double aspect = 1;          // -particle_aspect c/a
  Vec3 axis{0, 0, 1};         // -particle_axis: initial symmetry axis
  bool randomAxes = false;    // -particle_orientation random: generated spheroids' axes uniform on the sphere
  double maxOverlap = 0.01;   // -particles_max_overlap: largest initial overlap, fraction of the mean diameter
  bool allFixed = false;      // -particles_fixed: every particle held in place (forces still measured)
  double roughWalls = 0;      // -particles_rough_walls: radius [m] of a layer of fixed spheres on each z wall (0: none)
  ContactConfig contact;
  LubricationParams lubrication; // -lub_*: activation and saturation defaults set by resolveDefaults
  double maskSupport = 0;     // set by the coupling: how far beyond a radius the mask reaches [m]
  int substeps = 1;           // -dem_substeps per fluid step
  double skin = 0.1;          // -dem_skin: neighbour-list skin as a fraction of the largest diameter
  double dragViscosity = 0;   // -dem_drag_viscosity: Stokes drag of a still liquid, DEM-only runs
  double implicitDrag = 1;    // -dem_implicit_drag: fraction of the Stokes resistance made implicit
  bool orientation = true;    // -dem_orientation: integrate the orientation quaternions
  bool trackAll = false;      // -track_particles all
  std::vector<std::int64_t> track; // -track_particles id,id,...

  bool any() const { return !file.empty() || lattice.set || random.set || packed.set || single.set || roughWalls > 0; }

  static ParticleConfig read();
  void validate() const;
  // The defaults that depend on the grid, the fluid and the contact law (the lubrication's
  // activation and saturation gaps); once, before a DemSolver is built (it requires them).
  void resolveDefaults(const Config& main);
};

} // namespace vp
