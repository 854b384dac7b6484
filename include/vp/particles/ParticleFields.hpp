#pragma once
// Every per-particle field, declared once (docs/particles.md, particle fields): its type, its
// member name (in ParticleStore as a vector, in ParticleRecord as a value), its checkpoint columns,
// and when it is synchronised. The store, the ghost and migration buffers and the checkpoint rows
// are all generated from this list (forEachParticleField), so a new property is one line here.
//   kCreate     sent when a ghost is created (identity, shape, kinematics)
//   kStep       sent to the ghosts every DEM sub-step
//   kShift      a position: shifted by the periodic image offset when sent to a ghost
//   kMigrate    sent to a new owner
//   kCheckpoint a column group of the checkpoint's particle rows (history has its own dataset)
// Derived fields (mass, inverse mass and inertia, xRebuild, wallTouch) are not listed: append()
// computes them from the listed ones.
#include "vp/core/Vec3.hpp"
#include "vp/interactions/ContactHistory.hpp"
#include "vp/particles/Quaternion.hpp"
#include <array>
#include <cstdint>
#include <type_traits>

namespace vp {

using WallSprings = std::array<Vec3, 6>;  // tangential springs against the six walls

enum ParticleSync : unsigned { kCreate = 1, kStep = 2, kShift = 4, kMigrate = 8, kCheckpoint = 16 };

// X(type, member, checkpoint columns, sync)
#define VP_PARTICLE_FIELDS(X)                                                                          \
  X(std::int64_t, id, "id", kCreate | kMigrate | kCheckpoint)                                          \
  X(double, radius, "radius", kCreate | kMigrate | kCheckpoint)                                        \
  X(double, density, "density", kCreate | kMigrate | kCheckpoint)                                      \
  X(std::uint8_t, flags, "flags", kCreate | kMigrate | kCheckpoint)                                    \
  X(Vec3, x, "x,y,z", kCreate | kStep | kShift | kMigrate | kCheckpoint)                               \
  X(Vec3, v, "vx,vy,vz", kCreate | kStep | kMigrate | kCheckpoint)                                     \
  X(Vec3, w, "wx,wy,wz", kCreate | kStep | kMigrate | kCheckpoint)                                     \
  X(Quaternion, q, "qw,qx,qy,qz", kCreate | kStep | kMigrate | kCheckpoint)                            \
  /* total force/torque of the last sub-step; the hydrodynamic ones held over the fluid step */       \
  X(Vec3, force, "fx,fy,fz", kMigrate | kCheckpoint)                                                   \
  X(Vec3, torque, "tx,ty,tz", kMigrate | kCheckpoint)                                                  \
  X(Vec3, fhyd, "fhx,fhy,fhz", kMigrate | kCheckpoint)                                                 \
  X(Vec3, thyd, "thx,thy,thz", kMigrate | kCheckpoint)                                                 \
  /* momentum and angular momentum of the fluid inside the particle at the last fluid step */         \
  X(Vec3, fluidMomentum, "pfx,pfy,pfz", kMigrate | kCheckpoint)                                        \
  X(Vec3, fluidAngularMomentum, "lfx,lfy,lfz", kMigrate | kCheckpoint)                                 \
  X(WallSprings, wallSpring, "wall_spring[6][3]", kMigrate | kCheckpoint)                              \
  /* mid-step velocities (a particle may migrate inside a sub-step) */                                \
  X(Vec3, vHalf, "", kMigrate)                                                                         \
  X(Vec3, wHalf, "", kMigrate)                                                                         \
  /* velocity and spin the fluid step saw: the implicit drag's anchor (DemSolver::relax) */            \
  X(Vec3, vSeen, "", kMigrate)                                                                         \
  X(Vec3, wSeen, "", kMigrate)                                                                         \
  /* springs against other particles (variable length: their own checkpoint dataset) */                \
  X(ContactHistory, history, "", kMigrate)

// Calls f(&ParticleStore::m, &ParticleRecord::m, "m", columns, std::integral_constant<unsigned, sync>)
// for every field, in the order of the list.
#define VP_VISIT_PARTICLE_FIELD(T, m, cols, sync) \
  f(&Store::m, &Record::m, #m, cols, std::integral_constant<unsigned, (sync)>{});
template <class Store, class Record, class F>
void forEachParticleField(F&& f)
{
  VP_PARTICLE_FIELDS(VP_VISIT_PARTICLE_FIELD)
}
#undef VP_VISIT_PARTICLE_FIELD

} // namespace vp
