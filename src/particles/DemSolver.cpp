#include "vp/particles/DemSolver.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Logging.hpp"
#include "vp/particles/Generators.hpp"
#include "vp/particles/ParticleCheckpoint.hpp"
#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <petscsys.h>
#include <sstream>

namespace vp {

namespace {

ContactLaw makeLaw(const Config& c, const ParticleConfig& pc)
{
  if (pc.contact.tcSteps > 0 && !(c.time.dt > 0))
    throw InputError("option -contact_tc_steps: needs a fixed fluid step -time_dt (or use -contact_tc)");
  return ContactLaw(pc.contact, c.time.dt);
}

// The gap of a non-sphere with squeeze radius^2 R2 (particles/Shape.hpp) as the lubrication model
// sees it: a sphere of radius sqrt(R2) at a wall has the same squeeze. The normal velocities of
// the two surface points alone: the correction is the squeeze (docs/shapes.md).
PairState squeezeState(const Vec3& n, double gap, double R2, const Vec3& vI, const Vec3& vJ, double mu)
{
  PairState st;
  st.normal = n;
  st.gap = gap;
  st.radiusI = std::sqrt(R2);
  st.radiusJ = kWallRadius;
  st.velocityI = dot(vI, n) * n;
  st.velocityJ = dot(vJ, n) * n;
  st.viscosity = mu;
  return st;
}

// One side of a non-sphere's gap for the tangential terms: the sphere osculating the surface at its
// nearest point p (outward normal m) with the Gaussian radius of curvature 1 / sqrt(k1 k2) there,
// its centre relative to the body's, moving with the body. A wall: the default.
struct OsculatingSphere {
  double radius = kWallRadius;
  Vec3 centre, velocity, spin;
};

OsculatingSphere osculating(const Tensor3& K, const Vec3& p, const Vec3& m, const Vec3& v, const Vec3& w)
{
  const std::array<double, 2> k = tangentEigenvalues(K, m);
  const double R = 1 / std::sqrt(k[0] * k[1]);
  const Vec3 centre = p - R * m;
  return {R, centre, v + cross(w, centre), w};
}

// The tangential terms of the lubrication model across a non-sphere's gap (docs/shapes.md): those of
// the two osculating spheres (st: normal, gap, viscosity, wall slip), their force and torques acting
// on the bodies, the torques moved to the bodies' centres. The normal part is the squeeze's (left out).
PairForce shapedShear(const LubricationParams& film, PairState st, const OsculatingSphere& i, const OsculatingSphere& j,
                      double contactGap, double scale)
{
  st.radiusI = i.radius;
  st.radiusJ = j.radius;
  st.velocityI = i.velocity;
  st.velocityJ = j.velocity;
  st.angularVelocityI = i.spin;
  st.angularVelocityJ = j.spin;
  const PairForce f = lubricationForce(film, st, contactGap, scale);
  const Vec3 t = st.tangential(f.forceI);
  return {t, f.torqueI + cross(i.centre, t), f.torqueJ - cross(j.centre, t)};
}

} // namespace

DemSolver::DemSolver(const Grid& grid, const Config& c, const ParticleConfig& pc)
  : DemSolver(grid, c, pc, initialParticles(pc, c))
{
}

DemSolver::DemSolver(const Grid& grid, const Config& c, const ParticleConfig& pc, const std::vector<ParticleRecord>& all,
                     bool restart)
  : grid_(grid), pc_(pc), law_(makeLaw(c, pc)), lub_(pc.lubrication), mu_(c.fluid.mu), rho_(c.fluid.rho),
    gravity_(c.gravity), walls_(domainWalls(c)), hydro_(!c.fluid.off), drag_(pc.implicitDrag),
    handOff_(c.fluid.off ? ContactHydro::Keep : pc.contact.hydro,
             pc.contact.departureCells * std::min({grid.h(0), grid.h(1), grid.h(2)}), pc.contact.hydroHistory, c.fluid.rho,
             c.fluid.mu, c.gravity)
{
  if (!pc.lubrication.resolved()) throw std::logic_error("DemSolver: ParticleConfig::resolveDefaults was not called");
  for (int f = 0; f < 6; ++f) {
    if (walls_[f].active) activeWalls_.push_back(f);
    // Periodic faces are pushed to infinity for the quick wall-proximity test.
    const double far = walls_[f].active ? walls_[f].position : (f % 2 ? HUGE_VAL : -HUGE_VAL);
    (f % 2 ? wallHi_ : wallLo_)[f / 2] = far;
  }
  setUp(all, restart);
  if (c.time.dt > 0 && c.time.dt / pc_.substeps > lubStableSubstep_) {
    // The bound is for the closest approach; many runs never get there: watch the pairs instead.
    lubWatch_ = true;
    PetscPrintf(grid_.comm(), "vpsolve: warning: the DEM sub-step %g s exceeds %g s, the stability bound of the saturated lubrication "
                "(-dem_substeps %ld would keep every gap stable); the run stops with an error if a pair comes close enough to be unstable\n",
                c.time.dt / pc_.substeps, lubStableSubstep_, requiredSubsteps(c.time.dt / pc_.substeps));
  }
}

void DemSolver::setUp(const std::vector<ParticleRecord>& all, bool restart)
{
  for (const ParticleRecord& r : all) {
    rmax_ = std::max(rmax_, Shape{r.radius, r.aspect.value}.boundingRadius());
    shaped_ = shaped_ || r.aspect.value != 1;
  }
  if (rmax_ == 0) rmax_ = pc_.radius;
  if (shaped_) checkShapes(all);
  skin_ = pc_.skin * 2 * rmax_;
  // Lubrication acts below the activation gap; it holds constant below the roughness gap, where
  // contact takes over. DEM-only runs have no grid to tie the activation to: it must be given.
  lub_.checkRadius(rmax_);
  if (lub_.model != LubModel::None) {
    lubGap_ = std::max(lub_.reach(rmax_), handOff_.departureGap());  // pairs stay listed while they depart
    // Implicit squeeze: the explicit bound is gone (the tangential terms' logarithmic resistance stays explicit).
    lubStableSubstep_ = lub_.implicitSqueeze ? HUGE_VAL : 0.5 / lubricationRate(all);
  }
  // Halo: the farthest partner of a particle at list build (contact or lubrication range + skin).
  // Also every sphere that reaches into the subdomain with its penalization mask.
  const double halo = std::max(2 * rmax_ * (1 + law_.roughness()) + lubGap_ + skin_, rmax_ + pc_.maskSupport);
  exchange_ = std::make_unique<ParticleExchange>(grid_, halo);
  for (const ParticleRecord& r : all)
    if (exchange_->owns(r.x)) store_.append(r);
  store_.nOwned = store_.size();
  // A checkpoint written with other -contact_hydro options: their flags do not apply here.
  handOff_.dropStale(store_);
  rebuild();
  // Initial forces (zero step: springs keep their state). A restart has those of the last
  // sub-step, computed from the predicted velocities: recomputing them would change the run.
  if (!restart) computeForces(0);
}

// What the non-spheres can do so far (docs/shapes.md): contacts and the explicit lubrication
// (squeeze and tangential terms) with walls and any particle; not the implicit squeeze nor the
// film's inertia.
void DemSolver::checkShapes(const std::vector<ParticleRecord>& all) const
{
  if (lub_.model != LubModel::None && lub_.implicitSqueeze)
    failOption("-lub_integration", "implicit is for spheres: the squeeze of a spheroid is explicit (use explicit)");
  if (lub_.model != LubModel::None && lub_.inertia)
    failOption("-lub_inertia", "the film's inertia is that of a sphere at a wall: not for spheroids (drop the option)");
  if (lub_.replace)
    failOption("-lub_coupling", "replace takes the gap patches of spheres: use add with spheroids");
  const double h = std::max({grid_.h(0), grid_.h(1), grid_.h(2)});
  for (const ParticleRecord& r : all) {
    const Shape g{r.radius, r.aspect.value};
    if (hydro_ && 2 * g.smallestSemiAxis() < 2 * h)
      failOption(pc_.spheroid ? "-particle_aspect" : "-particles_file",
                 "the spheroid " + std::to_string(r.id) + "'s thickness 2 min(a, c) = " + formatNumber(2 * g.smallestSemiAxis()) +
                     " m spans less than two cells (" + formatNumber(2 * h) + " m): the mask cannot resolve it");
  }
}

void DemSolver::saveState(StateWriter& w)
{
  // Between rebuilds the springs live in the pair list; lend them to the histories.
  pairs_.exportHistory(store_);
  std::vector<ParticleRecord> owned;
  for (std::size_t i = 0; i < store_.nOwned; ++i) {
    owned.push_back(store_.record(i));
    store_.history[i].clear();
  }
  saveParticles(w, owned);
}

bool DemSolver::needRebuild() const
{
  const double limit = 0.25 * skin_ * skin_;  // (skin / 2)^2: no pair can have closed the skin
  int local = 0;
  for (std::size_t i = 0; i < store_.nOwned && !local; ++i) {
    const Vec3 d = store_.x[i] - store_.xRebuild[i];
    local = dot(d, d) > limit;
  }
  int global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, grid_.comm());
  return global;
}

void DemSolver::rebuild()
{
  StageScope stage(Stage::Exchange);
  ParticleStore& s = store_;
  // The histories are empty between rebuilds (restart: they hold the checkpoint's springs).
  pairs_.exportHistory(s);
  exchange_->migrate(s);
  exchange_->createGhosts(s);
  Vec3 lo, hi;
  const double h = exchange_->halo();
  for (int d = 0; d < 3; ++d) {
    lo[d] = exchange_->boxLo(d) - h;
    hi[d] = exchange_->boxHi(d) + h;
  }
  buckets_.build(s.x, s.size(), lo, hi, h);
  pairs_.build(s, buckets_, skin_, law_, lubGap_);
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    s.history[i].clear();
    s.xRebuild[i] = s.x[i];
  }
  ++rebuilds_;
}

void DemSolver::computeForces(double dt)
{
  ParticleStore& s = store_;
  PairList& P = pairs_;
  const double rough = law_.roughness();
  // Ghost entries collect partial sums too (never used): no branch in the scatter.
  for (std::size_t i = 0; i < s.size(); ++i) s.force[i] = s.torque[i] = Vec3{};
  handOff_.startForces(s);
  long contacts = 0;
  const bool lubricated = lub_.model != LubModel::None;
  if (lub_.implicitSqueeze) squeezePairs_.clear();
  for (std::size_t k = 0; k < P.size(); ++k) {
    const std::uint32_t i = P.first[k], j = P.second[k];
    if (shaped_ && !(s.sphere(i) && s.sphere(j))) {
      contacts += shapedPair(k, dt) && i < s.nOwned;
      continue;
    }
    const Vec3 d = s.x[i] - s.x[j];
    const double r2 = dot(d, d);
    const double reach = (s.radius[i] + s.radius[j]) * (1 + rough);
    const bool touching = r2 < reach * reach;
    if (!touching && P.touching[k]) {  // released: the spring is dropped
      P.spring[k] = Vec3{};
      P.touching[k] = 0;
    }
    if (!touching && !lubricated) continue;  // most listed pairs of a dry packing: no square root
    const double r = std::sqrt(r2);
    const double gap = r - s.radius[i] - s.radius[j];
    const double amin = std::min(s.radius[i], s.radius[j]);
    const Vec3 n = (1 / r) * d;
    // Leaving each other after an impact, closer than the departure gap: as at a wall, the resolved
    // force of both stays excluded and the correction stands for the film below that gap.
    const bool leaving = handOff_.pairLeaving(s, i, j, n, gap, P.departure[k]);
    // Hand-off: lubrication only while the surfaces are apart; in contact the contact law alone acts.
    const double replaced = lubricated && patches_ ? patches_->replaced(s.id[i], s.id[j]) : 0;
    const bool lubricating = lubricated && !touching && (gap < lub_.activationGap(amin) || leaving || replaced > 0);
    std::uint8_t impact = 0;
    if (!touching && !lubricating) {
      P.departure[k] = 0;
      continue;
    }
    Vec3 force, torqueI, torqueJ;
    if (touching) {
      P.touching[k] = 1;
      // Lever arms r a_i / (a_i + a_j) add up to r, so the pair conserves angular momentum.
      const double scale = r / (s.radius[i] + s.radius[j]);
      const Vec3 vc = contactVelocity(s.v[i], s.w[i], scale * s.radius[i], s.v[j], s.w[j], scale * s.radius[j], n);
      const ContactCoefficients& law = P.laws[P.law[k]];
      const ContactForce f = contactForce(n, reach - r, vc, law, P.spring[k], dt);
      noteOverlap((reach - r) / (2 * amin), s.id[i], s.id[j]);
      force = f.normal + f.tangential;
      if (stress_.on() && i < s.nOwned) stress_.addPair(PairStress::Contact, s.x[i], d, force, s.fixed(i), s.fixed(j));
      const Vec3 lever = scale * cross(n, f.tangential);
      const Vec3 roll = rollingTorque(n, s.w[i] - s.w[j], law.kn * (reach - r), law.muR, s.radius[i], s.radius[j],
                                      s.invInertia[i] + s.invInertia[j], dt);
      torqueI = roll - s.radius[i] * lever;
      torqueJ = -roll - s.radius[j] * lever;
      contacts += i < s.nOwned;  // counted by the owner of the lower id: once over all ranks
      impact = handOff_.touchPair(s, i, j, reach - r, law.kn);
    }
    P.departure[k] = handOff_.pairState(s, i, j, impact, leaving);
    if (lubricating) {
      PairState st;
      st.normal = -n;  // from i towards j
      st.gap = gap;
      st.radiusI = s.radius[i];
      st.radiusJ = s.radius[j];
      st.velocityI = s.v[i];
      st.velocityJ = s.v[j];
      st.angularVelocityI = s.w[i];
      st.angularVelocityJ = s.w[j];
      st.viscosity = mu_;
      const LubricationParams& film = leaving ? handOff_.departureFilm(lub_, amin) : lub_;
      PairForce l = lubricationForce(film, st, rough * (s.radius[i] + s.radius[j]), 0, replaced);
      if (lubWatch_) watchLubrication(st, rough * (s.radius[i] + s.radius[j]), s.invMass[i] + s.invMass[j]);
      if (lub_.implicitSqueeze) {
        // The squeeze c (dh/dt) n leaves the explicit force: each sphere takes it implicitly (substep).
        const double c = squeezeResistance(film, st, rough * (s.radius[i] + s.radius[j]));
        l.forceI -= (c * dot(s.v[j] - s.v[i], st.normal)) * st.normal;
        squeezePairs_.push_back({i, j, -1, c, st.normal, d});
      }
      if (stress_.on() && i < s.nOwned) stress_.addPair(PairStress::Lubrication, s.x[i], d, l.forceI, s.fixed(i), s.fixed(j));
      force += l.forceI;
      torqueI += l.torqueI;
      torqueJ += l.torqueJ;
    }
    // Pairs are sorted by (first id, second id): each particle receives in ascending partner id.
    s.force[i] += force;
    s.torque[i] += torqueI;
    s.force[j] -= force;
    s.torque[j] += torqueJ;
  }

  long wallContacts = 0;
  double coefMass = -1;  // wall coefficients depend on the mass only: reuse them along equal masses
  ContactCoefficients wallCoef;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    Vec3 F = s.force[i], T = s.torque[i];
    if (shaped_ && !s.sphere(i)) {
      wallContacts += spheroidWalls(i, F, T, dt);
      s.force[i] = F + s.mass[i] * gravity_;
      s.torque[i] = T;
      continue;
    }
    const double a = s.radius[i], reach = a * (1 + 2 * rough);
    const double lubReach = lubricated ? a + lub_.activationGap(a) : 0;
    const bool candidate = s.flags[i] & kDeparting;
    bool departing = false;
    // Walls after all particle partners, in face order (as if their ids followed every particle's).
    // A wall pair replaced at the step's start keeps its squeeze while it moves beyond h_act.
    if (s.wallTouch[i] || nearWall(s.x[i], std::max({reach, lubReach, candidate ? a + handOff_.departureGap() : 0.0})) ||
        (patches_ && patches_->replacedAtWall(s.id[i]))) {
      std::uint8_t touch = 0;
      for (int f : activeWalls_) {
        const Wall& wall = walls_[f];
        const double dist = wall.distance(s.x[i]);
        const double overlap = reach - dist;
        const Vec3 n = wall.normal();
        Vec3& spring = s.wallSpring[i][f];
        if (overlap <= 0 || s.fixed(i)) {
          spring = Vec3{};  // released: the spring is dropped
        } else {
          touch |= 1 << f;
          // The contact point lies on the wall plane: lever arm = distance.
          const Vec3 vc = s.v[i] - cross(dist * s.w[i], n) - wall.velocity;
          if (s.mass[i] != coefMass) {
            coefMass = s.mass[i];
            wallCoef = law_.coefficients(coefMass, true);
          }
          const ContactForce c = contactForce(n, overlap, vc, wallCoef, spring, dt);
          noteOverlap(overlap / (2 * a), s.id[i], -1 - f);
          F += c.normal + c.tangential;
          if (stress_.on()) stress_.addWall(PairStress::Contact, f, c.normal + c.tangential);
          T -= dist * cross(n, c.tangential);
          T += rollingTorque(n, s.w[i], wallCoef.kn * overlap, wallCoef.muR, a, 0, s.invInertia[i], dt);
          ++wallContacts;
          handOff_.touchWall(s, i, overlap, wallCoef.kn);
        }
        // Moving away from the wall after an impact, still in contact (below the buoyant-weight
        // overlap) or within the departure gap: the mask's sub-cell gap is not the squeeze
        // (docs/collisions.md), so the correction stands for the film below the departure gap.
        const bool leaving = handOff_.wallLeaving(s, i, wall.velocity, n, dist - a);
        departing = departing || leaving;
        const double replaced = lubricated && patches_ ? patches_->replaced(s.id[i], -1 - f) : 0;
        if (overlap <= 0 && (dist < lubReach || ((leaving || replaced > 0) && lubricated))) {  // hand-off: no lubrication in contact
          PairState st;
          st.normal = -n;  // from the centre towards the wall
          st.gap = dist - a;
          st.radiusI = a;
          st.radiusJ = kWallRadius;
          st.velocityI = s.v[i];
          st.velocityJ = wall.velocity;
          st.angularVelocityI = s.w[i];
          st.viscosity = mu_;
          st.density = rho_;
          st.slipWall = wall.slip;
          const LubricationParams& film = leaving ? handOff_.departureFilm(lub_, a) : lub_;
          PairForce l = lubricationForce(film, st, 2 * rough * a, 0, replaced);
          if (lubWatch_) watchLubrication(st, 2 * rough * a, s.invMass[i]);
          if (lub_.implicitSqueeze) {
            const double c = squeezeResistance(film, st, 2 * rough * a);
            l.forceI -= (c * dot(wall.velocity - s.v[i], st.normal)) * st.normal;
            squeezePairs_.push_back({i, 0, f, c, st.normal, st.normal});
          }
          F += l.forceI;
          if (stress_.on()) stress_.addWall(PairStress::Lubrication, f, l.forceI);
          T += l.torqueI;
        }
      }
      s.wallTouch[i] = touch;
    }
    handOff_.endWalls(s, i, departing);
    s.force[i] = F + s.mass[i] * gravity_;
    s.torque[i] = T;
  }
  if (pc_.dragViscosity > 0) addStokesDrag();
  contacts_ = contacts;
  wallContacts_ = wallContacts;
}

// The forces across a gap with a non-sphere (particles/Shape.hpp), particles and walls alike (a wall
// is a half-space: flat, still or sliding): n the unit normal from i towards j, gap the signed
// distance between the two surface points, the forces acting at the sides' lever points. Touching
// (gap below contactGap, a law given): the spring-dashpot and Coulomb law of spheres along n. Apart,
// within the activation gap (in units of scale) or leaving: the squeeze of the lubrication model at
// the gap's curvatures and the osculating spheres' tangential terms (docs/shapes.md).
PairForce DemSolver::gapForce(const GapSide& i, const GapSide& j, const Vec3& n, double gap, double contactGap, double scale,
                              const ContactCoefficients* law, Vec3& spring, bool leaving, bool slip, double invMassSum, double dt,
                              bool& touching)
{
  const Vec3 vI = i.v + cross(i.w, i.lever), vJ = j.v + cross(j.w, j.lever);
  const double overlap = contactGap - gap;
  touching = law && overlap > 0;
  if (touching) {
    const ContactForce f = contactForce(-n, overlap, vI - vJ, *law, spring, dt);  // the normal towards i
    const Vec3 F = f.normal + f.tangential;
    return {F, cross(i.lever, F), cross(F, j.lever)};
  }
  spring = Vec3{};  // released: the spring is dropped
  if (lub_.model == LubModel::None || overlap > 0 || !(gap < lub_.activationGap(scale) || leaving)) return {};
  auto curvature = [](const GapSide& b) { return b.shape ? rotatedTensor(b.shape->curvature(toBody(b.q, b.point)), b.q) : Tensor3{}; };
  const Tensor3 Ki = curvature(i), Kj = curvature(j);
  Tensor3 K;
  for (int m = 0; m < 9; ++m) K[m] = Ki[m] + Kj[m];
  const std::array<double, 2> k = tangentEigenvalues(K, n);
  PairState st = squeezeState(n, gap, squeezeRadiusSquared(k[0], k[1]), vI, vJ, mu_);
  st.slipWall = slip;
  const LubricationParams& film = leaving ? handOff_.departureFilm(lub_, scale) : lub_;
  const Vec3 squeeze = lubricationForce(film, st, contactGap, scale).forceI;
  const OsculatingSphere oj = j.shape ? osculating(Kj, j.point, -n, j.v, j.w) : OsculatingSphere{kWallRadius, {}, j.v, {}};
  const PairForce shear = shapedShear(film, st, osculating(Ki, i.point, n, i.v, i.w), oj, contactGap, scale);
  if (lubWatch_) watchLubrication(st, contactGap, invMassSum, scale);
  return {squeeze + shear.forceI, cross(i.lever, squeeze) + shear.torqueI, shear.torqueJ + cross(squeeze, j.lever)};
}

// A pair with a non-sphere: its gap between the bodies' nearest points (closestPoints; when they
// overlap, the deepest ones), the forces at the midpoint of the two points, each body taking the
// torque of its lever; the contact at the spheres' gap (roughness x the sum of the equatorial radii),
// no rolling resistance. Returns whether the pair touches.
bool DemSolver::shapedPair(std::size_t k, double dt)
{
  ParticleStore& s = store_;
  PairList& P = pairs_;
  const std::uint32_t i = P.first[k], j = P.second[k];
  const Shape gi = s.shape(i), gj = s.shape(j);
  const Vec3 d = s.x[j] - s.x[i];
  const ClosestPoints c = closestPoints(gi, s.q[i], gj, s.q[j], d, d);
  const double contactGap = law_.roughnessGap(gi.a, gj.a);
  const Vec3 mid = 0.5 * (c.pI + d + c.pJ);  // from the centre of i
  const GapSide bodyI{c.pI, mid, s.v[i], s.w[i], &gi, s.q[i]}, bodyJ{c.pJ, mid - d, s.v[j], s.w[j], &gj, s.q[j]};
  const ContactCoefficients& law = P.laws[P.law[k]];
  const bool leaving = handOff_.pairLeaving(s, i, j, -c.n, c.gap, P.departure[k]);
  bool touching = false;
  const PairForce f = gapForce(bodyI, bodyJ, c.n, c.gap, contactGap, std::min(gi.a, gj.a), &law, P.spring[k], leaving, false,
                               s.invMass[i] + s.invMass[j], dt, touching);
  P.touching[k] = touching;
  if (touching) {
    const double overlap = contactGap - c.gap;
    noteOverlap(overlap / (2 * std::min(gi.smallestSemiAxis(), gj.smallestSemiAxis())), s.id[i], s.id[j]);
    P.departure[k] = handOff_.pairState(s, i, j, handOff_.touchPair(s, i, j, overlap, law.kn), false);
  } else {
    P.departure[k] = handOff_.pairState(s, i, j, 0, leaving);
  }
  if (stress_.on() && i < s.nOwned && dot(f.forceI, f.forceI) > 0)
    stress_.addPair(touching ? PairStress::Contact : PairStress::Lubrication, s.x[i], -d, f.forceI, s.fixed(i),
                    s.fixed(j));
  s.force[i] += f.forceI;
  s.torque[i] += f.torqueI;
  s.force[j] -= f.forceI;
  s.torque[j] += f.torqueJ;
  return touching;
}

// The walls of a non-sphere: each a half-space met at the body's surface point whose outward normal
// points into the wall (gap: the centre's distance minus the extent along it), the forces of
// gapForce acting at mid-gap (so a tilted spheroid is turned by them), the contact at the spheres'
// gap (2 x roughness x the equatorial radius). No rolling resistance (a non-sphere resists rolling
// by its shape). Returns the number of walls touched.
int DemSolver::spheroidWalls(std::size_t i, Vec3& F, Vec3& T, double dt)
{
  ParticleStore& s = store_;
  const Shape g = s.shape(i);
  const double reachBeyond = law_.roughnessGap(g.a, 0);
  const double lubReach = lub_.model != LubModel::None ? lub_.activationGap(g.a) : 0;
  int touching = 0;
  bool departing = false;
  std::uint8_t touch = 0;
  if (s.wallTouch[i] || nearWall(s.x[i], g.boundingRadius() + std::max({reachBeyond, lubReach, handOff_.departureGap()}))) {
    const ContactCoefficients coef = law_.coefficients(s.mass[i], true);
    for (int f : activeWalls_) {
      const Wall& wall = walls_[f];
      const Vec3 n = -wall.normal();  // from the body towards the wall
      const Vec3 towardWall = toBody(s.q[i], n);
      const Vec3 p = toSpace(s.q[i], g.pointWithNormal(towardWall));
      const double gap = wall.distance(s.x[i]) - g.extent(towardWall);
      const bool leaving = handOff_.wallLeaving(s, i, wall.velocity, wall.normal(), gap);
      departing = departing || leaving;
      bool contact = false;
      const PairForce w = gapForce({p, p + (0.5 * gap) * n, s.v[i], s.w[i], &g, s.q[i]}, {{}, {}, wall.velocity, {}, nullptr, {}}, n, gap,
                                   reachBeyond, g.a, s.fixed(i) ? nullptr : &coef, s.wallSpring[i][f], leaving, wall.slip, s.invMass[i], dt,
                                   contact);
      if (contact) {
        touch |= 1 << f;
        ++touching;
        noteOverlap((reachBeyond - gap) / (2 * g.smallestSemiAxis()), s.id[i], -1 - f);
        handOff_.touchWall(s, i, reachBeyond - gap, coef.kn);
      }
      if (stress_.on() && dot(w.forceI, w.forceI) > 0) stress_.addWall(contact ? PairStress::Contact : PairStress::Lubrication, f, w.forceI);
      F += w.forceI;
      T += w.torqueI;
    }
  }
  s.wallTouch[i] = touch;
  handOff_.endWalls(s, i, departing);
  return touching;
}

// A still liquid acting on each particle alone (-dem_drag_viscosity): a sedimentation without
// hydrodynamic interactions, for preparing packings at a low Stokes number. The velocities are the
// predicted ones the other forces see; explicit, stable while dt < m / (3 pi mu d), far above
// the contact sub-step for any particle a DEM resolves.
void DemSolver::addStokesDrag()
{
  ParticleStore& s = store_;
  const double mu = pc_.dragViscosity;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const double d = 2 * s.radius[i];
    s.force[i] -= (3 * M_PI * mu * d) * s.v[i];
    s.torque[i] -= (M_PI * mu * d * d * d) * s.w[i];
  }
}

OverlapRecord DemSolver::takeLargestOverlap()
{
  const OverlapRecord r = largestOverlap_;
  largestOverlap_ = OverlapRecord{};
  return r;
}

bool DemSolver::nearWall(const Vec3& x, double reach) const
{
  return (x.x - wallLo_.x < reach) || (wallHi_.x - x.x < reach) || (x.y - wallLo_.y < reach) ||
         (wallHi_.y - x.y < reach) || (x.z - wallLo_.z < reach) || (wallHi_.z - x.z < reach);
}

void DemSolver::substep(double dt)
{
  if (hydro_)
    substep<true>(dt);
  else
    substep<false>(dt);
}

template <bool Hydro>
void DemSolver::substep(double dt)
{
  ParticleStore& s = store_;
  const double half = 0.5 * dt;
  // Velocity Verlet: half kick, drift, forces at the new positions, half kick. The forces see
  // the predicted end-of-step velocities v^n + dt a^n (sent to ghosts), which makes the velocity-
  // dependent damping second order (at the half-step velocity restitution errs by 1-3 % at 50
  // steps per contact).
  // Fixed particles have zero inverse mass and inertia: their velocities stay as given (a prescribed
  // motion, at rest by default), with no branch.
  auto kickV = [&](std::size_t i) {
    return Hydro ? handOff_.halfKick(s, i, half, s.force[i] + handOff_.resolvedForce(s, i)) : (half * s.invMass[i]) * s.force[i];
  };
  auto kickW = [&](std::size_t i) {
    const Vec3 T = Hydro ? s.torque[i] + handOff_.resolvedTorque(s, i) : s.torque[i];
    return !shaped_ || s.sphere(i) ? (half * s.invInertia[i]) * T : s.spinChange(i, half * T);
  };
  if (lub_.implicitSqueeze) {
    // Each half kick ends with the squeeze over the half step, implicitly (solveSqueeze).
    std::vector<Vec3> dv(s.nOwned), dw(s.nOwned);
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      dv[i] = kickV(i);
      dw[i] = kickW(i);
      s.v[i] += dv[i];
      s.w[i] += dw[i];
      if (Hydro) relax(i, half, s.v[i], s.w[i]);
    }
    solveSqueeze(half);
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      s.vHalf[i] = s.v[i];
      s.wHalf[i] = s.w[i];
      s.x[i] += dt * s.vHalf[i];
      s.v[i] = s.vHalf[i] + dv[i];
      s.w[i] = s.wHalf[i] + dw[i];
      if (Hydro) relax(i, half, s.v[i], s.w[i]);
    }
  } else {
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      const Vec3 dv = kickV(i), dw = kickW(i);
      s.vHalf[i] = s.v[i] + dv;
      s.wHalf[i] = s.w[i] + dw;
      if (Hydro) relax(i, half, s.vHalf[i], s.wHalf[i]);
      s.x[i] += dt * s.vHalf[i];  // a fixed particle moves with its prescribed, constant velocity
      s.v[i] = s.vHalf[i] + dv;
      s.w[i] = s.wHalf[i] + dw;
      if (Hydro) relax(i, half, s.v[i], s.w[i]);
    }
  }
  // A loop of its own: independent rotations pipeline better than inside the kick. A non-sphere
  // turns at constant angular momentum between the kicks (Euler's equations, the gyroscopic term
  // included), at the spin of the half-turned body (the midpoint rule: second order).
  if (shaped_)
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      if (s.sphere(i)) {
        s.q[i] = rotated(s.q[i], s.wHalf[i], dt);
        continue;
      }
      const Quaternion before = s.q[i], mid = rotated(before, s.wHalf[i], half);
      s.q[i] = rotated(before, s.carriedSpin(i, before, mid, s.wHalf[i]), dt);
      s.wHalf[i] = s.carriedSpin(i, before, s.q[i], s.wHalf[i]);
      s.w[i] = s.carriedSpin(i, before, s.q[i], s.w[i]);
    }
  else if (pc_.orientation)
    for (std::size_t i = 0; i < s.nOwned; ++i) s.q[i] = rotated(s.q[i], s.wHalf[i], dt);
  if (needRebuild())
    rebuild();
  else
    exchange_->updateGhosts(s);
  computeForces(dt);
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    s.v[i] = s.vHalf[i] + kickV(i);
    s.w[i] = s.wHalf[i] + kickW(i);
    if (Hydro) relax(i, half, s.v[i], s.w[i]);
  }
  if (lub_.implicitSqueeze) {
    solveSqueeze(half);
    if (stress_.on()) addSqueezeStress();
  }
  double ke = 0;
  for (std::size_t i = 0; i < s.nOwned; ++i)
    if (!s.fixed(i))
      ke += !shaped_ || s.sphere(i) ? s.mass[i] * (dot(s.v[i], s.v[i]) + 0.4 * s.radius[i] * s.radius[i] * dot(s.w[i], s.w[i])) : twiceKinetic(i);
  kineticEnergy_ = 0.5 * ke;
}

// -lub_integration implicit: the squeeze of every lubricated pair over a half kick dt, at its end,
// (M + dt C) v = M v*, with C the squeeze resistances c n n^T of the pairs and walls. Solved by Jacobi
// sweeps, each sphere's 3 x 3 block (I + dt/m sum c n n^T, inverted once) against its partners'
// velocities of the previous sweep, with a ghost update between sweeps: the same sweeps on any rank
// count (bitwise), until the largest change is below 1e-10 of the largest speed (docs/lubrication.md).
void DemSolver::solveSqueeze(double dt)
{
  ParticleStore& s = store_;
  const std::size_t n = s.nOwned;
  std::vector<std::array<double, 9>> A(n);  // per owned sphere: I + dt/m sum c n n^T, then its inverse
  for (std::size_t i = 0; i < n; ++i) A[i] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  auto add = [&](std::size_t k, const SqueezePair& p) {
    if (k >= n) return;
    const double w = dt * s.invMass[k] * p.c;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) A[k][3 * a + b] += w * p.n[a] * p.n[b];
  };
  for (const SqueezePair& p : squeezePairs_) {
    add(p.i, p);
    if (p.wall < 0) add(p.j, p);
  }
  for (std::array<double, 9>& M : A) {  // the inverse by the adjugate
    const std::array<double, 9> c = {M[4] * M[8] - M[5] * M[7], M[2] * M[7] - M[1] * M[8], M[1] * M[5] - M[2] * M[4],
                                      M[5] * M[6] - M[3] * M[8], M[0] * M[8] - M[2] * M[6], M[2] * M[3] - M[0] * M[5],
                                      M[3] * M[7] - M[4] * M[6], M[1] * M[6] - M[0] * M[7], M[0] * M[4] - M[1] * M[3]};
    const double det = M[0] * c[0] + M[1] * c[3] + M[2] * c[6];
    for (int k = 0; k < 9; ++k) M[k] = c[k] / det;
  }
  const std::vector<Vec3> vStar(s.v.begin(), s.v.begin() + n);
  exchange_->updateGhosts(s);  // the first sweep sees every partner's v* (bitwise on any rank count)
  std::vector<Vec3> B(s.size()), next(n);
  const MPI_Comm comm = grid_.comm();
  for (int sweep = 0;; ++sweep) {
    std::fill(B.begin(), B.end(), Vec3{});
    for (const SqueezePair& p : squeezePairs_) {
      const Vec3 partner = p.wall >= 0 ? walls_[p.wall].velocity : s.v[p.j];
      B[p.i] += (p.c * dot(p.n, partner)) * p.n;
      if (p.wall < 0) B[p.j] += (p.c * dot(p.n, s.v[p.i])) * p.n;
    }
    double local[2] = {0, 0};  // largest change, largest speed
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 r = vStar[i] + (dt * s.invMass[i]) * B[i];
      for (int a = 0; a < 3; ++a) next[i][a] = A[i][3 * a] * r.x + A[i][3 * a + 1] * r.y + A[i][3 * a + 2] * r.z;
      local[0] = std::max(local[0], norm(next[i] - s.v[i]));
      local[1] = std::max(local[1], norm(next[i]));
    }
    std::copy(next.begin(), next.end(), s.v.begin());
    exchange_->updateGhosts(s);
    MPI_Allreduce(MPI_IN_PLACE, local, 2, MPI_DOUBLE, MPI_MAX, comm);
    if (local[0] <= 1e-10 * local[1]) return;
    if (sweep == 10000)
      throw StepFailure("option -lub_integration implicit: the squeeze did not converge in 10000 sweeps (change " +
                        std::to_string(local[0]) + " m/s); lower the sub-step (-dem_substeps)");
  }
}

// The squeeze forces the sub-step applied, from the updated velocities, into the pair stress.
void DemSolver::addSqueezeStress()
{
  const ParticleStore& s = store_;
  for (const SqueezePair& p : squeezePairs_) {
    if (p.i >= s.nOwned) continue;  // a pair counts on the rank that owns its first sphere
    const Vec3 partner = p.wall >= 0 ? walls_[p.wall].velocity : s.v[p.j];
    const Vec3 force = (p.c * dot(partner - s.v[p.i], p.n)) * p.n;
    if (p.wall >= 0)
      stress_.addWall(PairStress::Lubrication, p.wall, force);
    else
      stress_.addPair(PairStress::Lubrication, s.x[p.i], p.d, force, s.fixed(p.i), s.fixed(p.j));
  }
}

double DemSolver::lubricationRate(const std::vector<ParticleRecord>& all) const
{
  if (shaped_) return shapedLubricationRate(all);
  // Particle classes (radius, inverse mass): the pair rate c (1/m_i + 1/m_j) over all class pairs.
  std::vector<std::pair<double, double>> classes;
  for (const ParticleRecord& r : all) {
    const double invMass = (r.flags & kFixed) ? 0 : 1 / (r.density * 4.0 / 3.0 * M_PI * std::pow(r.radius, 3));
    if (std::find(classes.begin(), classes.end(), std::make_pair(r.radius, invMass)) == classes.end())
      classes.emplace_back(r.radius, invMass);
    if (classes.size() > 64) break;
  }
  PairState geometry;
  geometry.normal = {0, 0, 1};
  geometry.viscosity = mu_;
  auto resistance = [&](double ai, double aj) {
    geometry.radiusI = ai;
    geometry.radiusJ = aj;
    const double contactGap = law_.roughnessGap(ai, std::isinf(aj) ? 0 : aj);
    // With the departure the correction may start from its larger gap: the larger resistance.
    return lubricationResistance(handOff_.departureGap() > 0 ? handOff_.departureFilm(lub_, std::min(ai, aj)) : lub_, geometry, contactGap);
  };
  double rate = 0, invMassMax = 0;
  for (const auto& [a, invMass] : classes) invMassMax = std::max(invMassMax, invMass);
  const bool exact = classes.size() <= 64;
  for (const auto& [ai, invMassI] : classes) {
    if (!activeWalls_.empty()) rate = std::max(rate, resistance(ai, kWallRadius) * invMassI);
    if (!exact)  // a sphere-wall resistance bounds that of any pair the sphere is the smaller of
      rate = std::max(rate, resistance(ai, kWallRadius) * (invMassI + invMassMax));
    else
      for (const auto& [aj, invMassJ] : classes) rate = std::max(rate, resistance(ai, aj) * (invMassI + invMassJ));
  }
  return rate;
}

// With non-spheres: the squeeze resistance of BLCM (which bounds LLCM's) at the largest R^2 each
// pair of shape classes can meet with (largestSqueezeRadiusSquared), at its smallest gap.
double DemSolver::shapedLubricationRate(const std::vector<ParticleRecord>& all) const
{
  struct ShapeClass {
    Shape g;
    double invMass;
    bool operator==(const ShapeClass& o) const { return g.a == o.g.a && g.aspect == o.g.aspect && invMass == o.invMass; }
  };
  std::vector<ShapeClass> classes;
  for (const ParticleRecord& r : all) {
    const Shape g{r.radius, r.aspect.value};
    const ShapeClass k{g, (r.flags & kFixed) ? 0 : 1 / g.mass(r.density)};
    if (std::find(classes.begin(), classes.end(), k) == classes.end()) classes.push_back(k);
  }
  auto rate = [&](const ShapeClass& i, const ShapeClass* j) {
    const double a = j ? std::min(i.g.a, j->g.a) : i.g.a;
    const double h = std::max(lub_.saturation * a, law_.roughnessGap(i.g.a, j ? j->g.a : 0));
    const double hAct = std::max(handOff_.departureGap(), lub_.activationGap(a));
    if (!(h < hAct)) return 0.0;
    const double R2 = largestSqueezeRadiusSquared(i.g, j ? &j->g : nullptr);
    return 6 * M_PI * mu_ * R2 * (1 / h - 1 / hAct) * (i.invMass + (j ? j->invMass : 0));
  };
  double worst = 0;
  for (std::size_t m = 0; m < classes.size(); ++m) {
    if (!activeWalls_.empty()) worst = std::max(worst, rate(classes[m], nullptr));
    for (std::size_t n = m; n < classes.size() && all.size() > 1; ++n) worst = std::max(worst, rate(classes[m], &classes[n]));
  }
  return worst;
}

long DemSolver::requiredSubsteps(double dtp) const
{
  return static_cast<long>(std::ceil(pc_.substeps * dtp / lubStableSubstep_));
}

void DemSolver::watchLubrication(const PairState& st, double contactGap, double invMassSum, double scale)
{
  // The BLCM resistance bounds the LLCM's (docs/lubrication.md): c = 6 pi mu R^2 (1/h - 1/h_act),
  // and 6 pi mu R^2 / h the whole squeeze of a replaced pair (-lub_coupling replace).
  const double a = scale > 0 ? scale : std::min(st.radiusI, st.radiusJ), R = st.reducedRadius();
  const double h = std::max({st.gap, lub_.saturation * a, contactGap});
  const double hAct = std::max(handOff_.departureGap(), lub_.activationGap(a));  // the departure's, if larger
  const double c = (st.slipWall ? 0.25 : 1) * 6 * M_PI * mu_ * R * R * (1 / h - (lub_.replace ? 0 : 1 / hAct));
  lubRateSeen_ = std::max(lubRateSeen_, c * invMassSum);
}

void DemSolver::checkLubricationSeen(double dtp)
{
  double worst = 0;
  MPI_Allreduce(&lubRateSeen_, &worst, 1, MPI_DOUBLE, MPI_MAX, grid_.comm());
  lubRateSeen_ = 0;
  if (worst * dtp <= 1) return;
  std::ostringstream msg;
  msg << "option -dem_substeps: the DEM sub-step " << dtp << " s is unstable for the lubrication of a pair at its gap (c dt_p / m* = "
      << worst * dtp << " > 1; the saturated resistance needs dt_p <= " << lubStableSubstep_
      << " s): raise -dem_substeps to at least " << requiredSubsteps(dtp) << ", or lower -time_dt, or raise -lub_saturation";
  throw StepFailure(msg.str());
}

// The implicit drag (-dem_implicit_drag k): within a fluid step the resolved force was computed for
// the velocity the fluid saw (vSeen); its response to the particle's own change of velocity is
// modelled by the Stokes resistance, F = F_resolved - k 6 pi mu a (v - vSeen) (and the torque with
// 8 pi mu a^3), taken implicitly in each half kick: v <- (v + c vSeen) / (1 + c), c = k C dt/(2m).
// A steady motion (v = vSeen) is unchanged; without it the held force overshoots once the fluid
// step exceeds the particle's viscous relaxation time (spin reverses every step and grows near
// walls and neighbours; docs/coupling.md).
double DemSolver::twiceKinetic(std::size_t i) const
{
  const ParticleStore& s = store_;
  const Vec3 b = toBody(s.q[i], s.w[i]), k = s.invInertiaBody[i];
  return s.mass[i] * dot(s.v[i], s.v[i]) + b.x * b.x / k.x + b.y * b.y / k.y + b.z * b.z / k.z;
}

void DemSolver::relax(std::size_t i, double half, Vec3& v, Vec3& w) const
{
  const ParticleStore& s = store_;
  if (drag_ == 0 || handOff_.resolvedOff(s, i)) return;
  // A non-sphere: the Stokes resistance of its equal-volume sphere, on its most mobile axis.
  const double a = !shaped_ || s.sphere(i) ? s.radius[i] : s.shape(i).equalVolumeRadius();
  const double cv = half * s.invMass[i] * drag_ * 6 * M_PI * mu_ * a;
  const double cw = half * s.invInertia[i] * drag_ * 8 * M_PI * mu_ * a * a * a;
  v = (1 / (1 + cv)) * (v + cv * s.vSeen[i]);
  w = (1 / (1 + cw)) * (w + cw * s.wSeen[i]);
}

void DemSolver::advance(double, double dt)
{
  StageScope stage(Stage::DEM);
  if (hydro_)
    for (std::size_t i = 0; i < store_.nOwned; ++i) {
      store_.vSeen[i] = store_.v[i];
      store_.wSeen[i] = store_.w[i];
    }
  const double dtp = dt / pc_.substeps;
  handOff_.startSubsteps(dtp);
  lubWatch_ = lubWatch_ || dtp > lubStableSubstep_;
  for (int m = 0; m < pc_.substeps; ++m) {
    substep(dtp);
    if (stress_.on()) stress_.endSubstep();
  }
  if (lubWatch_) checkLubricationSeen(dtp);
}

DemDiagnostics DemSolver::diagnostics() const
{
  double ke = kineticEnergy_;
  if (ke < 0) {  // before the first step
    ke = 0;
    const ParticleStore& s = store_;
    for (std::size_t i = 0; i < s.nOwned; ++i)
      if (!s.fixed(i)) ke += 0.5 * (!shaped_ || s.sphere(i) ? s.mass[i] * dot(s.v[i], s.v[i]) + dot(s.w[i], s.w[i]) / s.invInertia[i] : twiceKinetic(i));
  }
  double local[4] = {ke, double(store_.nOwned), double(contacts_), double(wallContacts_)}, global[4];
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_SUM, grid_.comm());
  DemDiagnostics d;
  d.kineticEnergy = global[0];
  d.particles = std::lround(global[1]);
  d.contacts = std::lround(global[2]);
  d.wallContacts = std::lround(global[3]);
  return d;
}

double DemSolver::suggestedStep() const
{
  double mmin = HUGE_VAL;
  for (std::size_t i = 0; i < store_.nOwned; ++i) mmin = std::min(mmin, store_.mass[i]);
  double g = 0;
  MPI_Allreduce(&mmin, &g, 1, MPI_DOUBLE, MPI_MIN, grid_.comm());
  if (!std::isfinite(g)) g = 4.0 / 3.0 * M_PI * std::pow(pc_.radius, 3) * pc_.density;
  return std::min({law_.contactTime(0.5 * g, false) / 50, law_.contactTime(g, true) / 50, lubStableSubstep_});
}

} // namespace vp
