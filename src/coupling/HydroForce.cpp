#include "vp/coupling/HydroForce.hpp"
#include "vp/coupling/Penalization.hpp"
#include <cmath>

namespace vp {

void hydroForces(ParticleStore& s, ParticleExchange& exchange, std::vector<double>& sums, double dt, double rho,
                 const Vec3& gravity)
{
  exchange.reduceToOwners(s, sums, kHydroSums);
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const double* sum = &sums[kHydroSums * i];
    const Vec3 penForce{sum[0], sum[1], sum[2]}, penTorque{sum[3], sum[4], sum[5]};
    const Vec3 momentum{sum[6], sum[7], sum[8]}, moment{sum[9], sum[10], sum[11]};
    if (dt > 0) {
      const double volume = s.shape(i).volume();
      s.fhyd[i] = penForce + (momentum - s.fluidMomentum[i]) / dt - (rho * volume) * gravity;
      s.thyd[i] = penTorque + (moment - s.fluidAngularMomentum[i]) / dt;
    }
    s.fluidMomentum[i] = momentum;
    s.fluidAngularMomentum[i] = moment;
  }
}

} // namespace vp
