#pragma once
// Every per-particle field, declared once (docs/particles.md, particle fields): its type, its
// member name (in ParticleStore as a vector, in ParticleRecord as a value), its checkpoint columns,
// its snapshot dataset, and when it is synchronised. The store, the ghost and migration buffers,
// the checkpoint rows and the snapshot datasets are all generated from this list
// (forEachParticleField), so a new property is one line here.
//   kCreate     sent when a ghost is created (identity, shape, kinematics)
//   kStep       sent to the ghosts every DEM sub-step
//   kShift      a position: shifted by the periodic image offset when sent to a ghost
//   kMigrate    sent to a new owner
//   kCheckpoint a column group of the checkpoint's particle rows (history and windowHistory have
//               their own datasets)
//   kSnapshot   a dataset of the particle snapshots (particles_<step>.h5, ParaView through XDMF)
// Derived fields (mass, inverse mass and inertia, xRebuild, wallTouch) are not listed: append()
// computes them from the listed ones.
#include "vp/core/Vec3.hpp"
#include "vp/interactions/BassetModes.hpp"
#include "vp/interactions/ContactHistory.hpp"
#include "vp/particles/Quaternion.hpp"
#include "vp/particles/Shape.hpp"
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace vp {

using WallSprings = std::array<Vec3, 6>;  // tangential springs against the six walls
// The history force's state of a particle inside an exclusion window (DemSolver::halfKick): its
// Basset modes, and the velocity change of a contact under way (recorded in them when it ends).
struct WindowHistory {
  BassetModes modes{};
  Vec3 contactChange;
};
// One entry inside a window, none elsewhere: a particle outside a window carries an empty vector.
using WindowModes = std::vector<WindowHistory>;

enum ParticleSync : unsigned { kCreate = 1, kStep = 2, kShift = 4, kMigrate = 8, kCheckpoint = 16, kSnapshot = 32 };

struct ParticleFieldInfo {
  const char* name;      // the member
  const char* columns;   // its checkpoint columns
  const char* snapshot;  // its snapshot dataset
};

// X(type, member, checkpoint columns, snapshot dataset, sync)
#define VP_PARTICLE_FIELDS(X)                                                                                         \
  X(std::int64_t, id, "id", "id", kCreate | kMigrate | kCheckpoint | kSnapshot)                                       \
  X(double, radius, "radius", "radius", kCreate | kMigrate | kCheckpoint | kSnapshot)                                 \
  /* polar over equatorial semi-axis (particles/Shape.hpp), 1 for a sphere; radius is the equatorial one */         \
  X(Aspect, aspect, "aspect", "aspect", kCreate | kMigrate | kCheckpoint | kSnapshot)                                 \
  X(double, density, "density", "", kCreate | kMigrate | kCheckpoint)                                                 \
  X(std::uint8_t, flags, "flags", "", kCreate | kMigrate | kCheckpoint)                                               \
  X(Vec3, x, "x,y,z", "position", kCreate | kStep | kShift | kMigrate | kCheckpoint | kSnapshot)                      \
  X(Vec3, v, "vx,vy,vz", "velocity", kCreate | kStep | kMigrate | kCheckpoint | kSnapshot)                            \
  X(Vec3, w, "wx,wy,wz", "angular_velocity", kCreate | kStep | kMigrate | kCheckpoint | kSnapshot)                    \
  X(Quaternion, q, "qw,qx,qy,qz", "orientation", kCreate | kStep | kMigrate | kCheckpoint | kSnapshot)                \
  /* total force/torque of the last sub-step; the hydrodynamic ones held over the fluid step */                       \
  X(Vec3, force, "fx,fy,fz", "", kMigrate | kCheckpoint)                                                              \
  X(Vec3, torque, "tx,ty,tz", "", kMigrate | kCheckpoint)                                                             \
  X(Vec3, fhyd, "fhx,fhy,fhz", "", kMigrate | kCheckpoint)                                                            \
  X(Vec3, thyd, "thx,thy,thz", "", kMigrate | kCheckpoint)                                                            \
  /* momentum and angular momentum of the fluid inside the particle at the last fluid step */                         \
  X(Vec3, fluidMomentum, "pfx,pfy,pfz", "", kMigrate | kCheckpoint)                                                   \
  X(Vec3, fluidAngularMomentum, "lfx,lfy,lfz", "", kMigrate | kCheckpoint)                                            \
  X(WallSprings, wallSpring, "wall_spring[6][3]", "", kMigrate | kCheckpoint)                                         \
  /* mid-step velocities (a particle may migrate inside a sub-step) */                                                \
  X(Vec3, vHalf, "", "", kMigrate)                                                                                    \
  X(Vec3, wHalf, "", "", kMigrate)                                                                                    \
  /* velocity and spin the fluid step saw: the implicit drag's anchor (DemSolver::relax) */                           \
  X(Vec3, vSeen, "", "", kMigrate)                                                                                    \
  X(Vec3, wSeen, "", "", kMigrate)                                                                                    \
  /* Basset history of the velocity changes while the resolved force is excluded (DemSolver; empty */                 \
  /* outside; their own checkpoint dataset, rows of the particles that have them)                 */                  \
  X(WindowModes, windowHistory, "", "", kMigrate)                                                                     \
  /* springs against other particles (variable length: their own checkpoint dataset) */                               \
  X(ContactHistory, history, "", "", kMigrate)

// A field as doubles (checkpoint rows, snapshot datasets): writeDoubles writes and advances o,
// readDoubles reads and advances o.
inline void writeDoubles(double v, double*& o) { *o++ = v; }
inline void writeDoubles(const Vec3& v, double*& o) { *o++ = v.x, *o++ = v.y, *o++ = v.z; }
inline void writeDoubles(const Aspect& a, double*& o) { *o++ = a.value; }
inline void writeDoubles(const Quaternion& q, double*& o) { *o++ = q.w, *o++ = q.x, *o++ = q.y, *o++ = q.z; }
inline void writeDoubles(const WallSprings& a, double*& o)
{
  for (const Vec3& v : a) writeDoubles(v, o);
}
inline void readDoubles(const double*& o, std::int64_t& v) { v = static_cast<std::int64_t>(*o++); }
inline void readDoubles(const double*& o, std::uint8_t& v) { v = static_cast<std::uint8_t>(*o++); }
inline void readDoubles(const double*& o, double& v) { v = *o++; }
inline void readDoubles(const double*& o, Vec3& v) { v.x = o[0], v.y = o[1], v.z = o[2], o += 3; }
inline void readDoubles(const double*& o, Aspect& a) { a.value = *o++; }
inline void readDoubles(const double*& o, Quaternion& q) { q = Quaternion{o[0], o[1], o[2], o[3]}, o += 4; }
inline void readDoubles(const double*& o, WallSprings& a)
{
  for (Vec3& v : a) readDoubles(o, v);
}
// Doubles per value of a field type.
template <class T>
int doublesOf()
{
  double row[32], *o = row;
  writeDoubles(T{}, o);
  return static_cast<int>(o - row);
}

// Calls f(&ParticleStore::m, &ParticleRecord::m, ParticleFieldInfo, std::integral_constant<unsigned, sync>)
// for every field, in the order of the list.
#define VP_VISIT_PARTICLE_FIELD(T, m, cols, snap, sync) \
  f(&Store::m, &Record::m, ParticleFieldInfo{#m, cols, snap}, std::integral_constant<unsigned, (sync)>{});
template <class Store, class Record, class F>
void forEachParticleField(F&& f)
{
  VP_PARTICLE_FIELDS(VP_VISIT_PARTICLE_FIELD)
}
#undef VP_VISIT_PARTICLE_FIELD

} // namespace vp
