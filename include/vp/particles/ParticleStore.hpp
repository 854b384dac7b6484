#pragma once
// Particle storage: struct of arrays, owned particles first ([0, nOwned)), then ghosts (copies of
// neighbours' particles, periodic images shifted). Global ids are unique and stable.
#include "vp/core/Vec3.hpp"
#include "vp/interactions/ContactHistory.hpp"
#include "vp/particles/Quaternion.hpp"
#include <array>
#include <cstdint>
#include <vector>

namespace vp {

// kFixed: infinite mass and inertia; moves with its given constant velocity and spin (a prescribed
// motion; held in place when they are zero).
// kResolvedForceOff: in a contact whose resolved hydrodynamic force is excluded (-contact_hydro),
// set by the DEM's force loop for the next kicks.
enum ParticleFlag : std::uint8_t { kFixed = 1, kResolvedForceOff = 2 };

// Everything one particle carries when it changes owner (docs/particles.md, parallel decomposition).
struct ParticleRecord {
  std::int64_t id = 0;
  double radius = 0, density = 0;
  std::uint8_t flags = 0;
  Vec3 x, v, w, force, torque, fhyd, thyd;
  Vec3 vHalf, wHalf;                  // a particle may migrate inside a sub-step
  Vec3 vSeen, wSeen;                  // velocity and spin the fluid step saw (implicit drag anchor)
  Vec3 fluidMomentum, fluidAngularMomentum; // of the fluid inside the particle, last fluid step
  Quaternion q;
  std::array<Vec3, 6> wallSpring{};   // tangential springs against the six walls
  ContactHistory history;             // springs against other particles
};

struct ParticleStore {
  // Sent on ghost creation and to a new owner.
  std::vector<std::int64_t> id;
  std::vector<double> radius, density;
  std::vector<std::uint8_t> flags;
  // Derived from radius and density (inverse mass and moment of inertia; 0 when fixed).
  std::vector<double> mass, invMass, invInertia;
  // Sent every sub-step to ghosts.
  std::vector<Vec3> x, v, w;
  std::vector<Quaternion> q;
  // Owned only (ghost entries unused): total force/torque of the last sub-step, the fixed
  // hydrodynamic force/torque of the current fluid step, springs and position at the last rebuild.
  std::vector<Vec3> force, torque, fhyd, thyd, xRebuild;
  std::vector<Vec3> vHalf, wHalf;   // mid-step velocities inside a DEM sub-step
  // Velocity and spin at the start of the fluid step's DEM sub-steps, which the penalization saw:
  // the anchor of the implicit drag (DemSolver::advance).
  std::vector<Vec3> vSeen, wSeen;
  // Momentum and angular momentum (about the centre) of the fluid inside the particle at the last
  // fluid step: their rate of change is part of the hydrodynamic force (coupling/HydroForce).
  std::vector<Vec3> fluidMomentum, fluidAngularMomentum;
  std::vector<std::array<Vec3, 6>> wallSpring;
  std::vector<std::uint8_t> wallTouch;   // bit f: wallSpring[f] may be non-zero (derived on append)
  std::vector<ContactHistory> history;

  std::size_t nOwned = 0;

  std::size_t size() const { return id.size(); }
  bool fixed(std::size_t i) const { return flags[i] & kFixed; }

  // Appends a particle (at the end: call only when there are no ghosts, or for ghosts).
  void append(const ParticleRecord& r);
  ParticleRecord record(std::size_t i) const;
  void resize(std::size_t n);
  // Keeps the owned particles with keep[i] != 0 (in order); requires no ghosts.
  void compactOwned(const std::vector<char>& keep);
  void dropGhosts() { resize(nOwned); }
};

} // namespace vp
