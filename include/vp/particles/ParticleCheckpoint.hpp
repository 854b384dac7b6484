#pragma once
// The particles' part of a checkpoint (core/StateArchive.hpp): one row per particle with the
// kCheckpoint fields of ParticleFields.hpp, named by the particle_columns text (a column is found by
// its name, so a new field reads from older checkpoints with its default value), the tangential
// springs with their departure states (contacts) and the Basset modes of the particles in a window
// (window_history).
#include "vp/core/StateArchive.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <vector>

namespace vp {

// Collective: this rank's particles with their springs.
void saveParticles(StateWriter& w, const std::vector<ParticleRecord>& owned);
// Collective: every particle (the same list on every rank), springs attached; a damaged table is
// an InputError naming -restart.
std::vector<ParticleRecord> loadParticles(const StateReader& r);

} // namespace vp
