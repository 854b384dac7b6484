#pragma once
// State of one lubrication pair (sphere-sphere or sphere-wall) and the force and torques it
// produces. A plane wall is the infinite-radius limit of a sphere: radiusJ = kWallRadius.
#include "vp/core/Vec3.hpp"
#include <cmath>
#include <limits>

namespace vp {

constexpr double kWallRadius = std::numeric_limits<double>::infinity();

struct PairState {
  Vec3 normal;                 // unit normal from the centre of i towards j (or the wall)
  double gap = 0;              // surface gap h [m]
  double radiusI = 0;          // a_i [m]
  double radiusJ = 0;          // a_j [m]; kWallRadius for a wall
  Vec3 velocityI, velocityJ;   // translational velocities [m/s] (a wall may slide)
  Vec3 angularVelocityI, angularVelocityJ; // [1/s]; a wall's is ignored
  double viscosity = 0;        // mu [Pa s]
  double density = 0;          // rho of the liquid [kg/m^3]: the gap's inertia (-lub_inertia); 0: none
  bool slipWall = false;       // the wall is free-slip (no shear stress on it)

  bool isWall() const { return std::isinf(radiusJ); }
  // Curvatures 1/a; a wall has zero curvature, which is how every formula takes the wall limit.
  double curvatureI() const { return 1 / radiusI; }
  double curvatureJ() const { return isWall() ? 0 : 1 / radiusJ; }
  // R = a_i a_j / (a_i + a_j): the parabolic gap is h(r) = h + r^2 / (2 R); R = a_i at a wall.
  double reducedRadius() const { return 1 / (curvatureI() + curvatureJ()); }
  // Rate of change of the gap, dh/dt = (v_j - v_i) . n (negative when approaching).
  double gapRate() const { return dot(velocityJ - velocityI, normal); }
  // Velocity of each surface at its point nearest the other body.
  Vec3 surfaceVelocityI() const { return velocityI + cross(angularVelocityI, radiusI * normal); }
  Vec3 surfaceVelocityJ() const
  {
    return isWall() ? velocityJ : velocityJ + cross(angularVelocityJ, -radiusJ * normal);
  }
  // Component of v in the plane normal to the line of centres.
  Vec3 tangential(const Vec3& v) const { return v - dot(v, normal) * normal; }
};

// j receives -forceI. Torques are about each sphere's centre; a wall takes no torque (zero).
// Which motions a model force is asked for: the squeeze (normal relative motion: the normal force
// alone) or the shear (sliding and rolling: the tangential terms alone), or both. A model is linear
// in the velocities, so a caller that splits the motion evaluates only the part its state carries.
enum class LubPart { Both, Squeeze, Shear };

struct PairForce {
  Vec3 forceI;
  Vec3 torqueI;
  Vec3 torqueJ;

  PairForce& operator+=(const PairForce& o)
  {
    forceI += o.forceI;
    torqueI += o.torqueI;
    torqueJ += o.torqueJ;
    return *this;
  }
  PairForce& operator-=(const PairForce& o)
  {
    forceI -= o.forceI;
    torqueI -= o.torqueI;
    torqueJ -= o.torqueJ;
    return *this;
  }
  PairForce& operator*=(double w)
  {
    forceI *= w;
    torqueI *= w;
    torqueJ *= w;
    return *this;
  }
};

} // namespace vp
