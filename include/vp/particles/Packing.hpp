#pragma once
// Dense random packings without overlaps (-particles_packed; docs/rheology.md): spheres placed at
// random in a box at a fraction of their size, then grown step by step while their overlaps are
// relaxed away (each overlapping pair pushed apart along its line of centres, walls pushing back),
// up to their radius plus a clearance. Reaches solid fractions to about 0.6; monodisperse or
// bidisperse (equal volumes of radius a and of radius ratio * a, which keeps the packing from
// crystallising). Axes along which the box spans a periodic domain wrap around.
#include "vp/core/Config.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <array>
#include <vector>

namespace vp {

// The spheres with ids 0..N-1 (the larger ones first). wrap[d]: the box is periodic along d.
// Every pair ends at least `clearance` of its radius sum apart (the contact law's roughness, so
// that no contact is loaded at the start), and more than 1.6e-3 of it.
// Throws InputError (-particles_packed) when the relaxation cannot reach the solid fraction.
std::vector<ParticleRecord> packedParticles(const PackedInput& in, double density, const std::array<bool, 3>& wrap,
                                            double clearance);

} // namespace vp
