#pragma once
// Initial particles: read from a file (CSV or HDF5 table) or generated (lattice, random packing,
// single particle), and rough walls of fixed spheres beside any of them. Every rank builds the same global list, so validation errors are collective.
#include "vp/core/Config.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <string>
#include <vector>

namespace vp {

// Columns of the particle CSV header and of the HDF5 table (one 1-D dataset each).
extern const char* const kParticleColumns[12];

std::vector<ParticleRecord> readParticleCsv(const std::string& path);
std::vector<ParticleRecord> readParticleHdf5(const std::string& path);
std::vector<ParticleRecord> latticeParticles(const LatticeInput& in, double density);
std::vector<ParticleRecord> randomParticles(const RandomInput& in, double density);
// Rough walls (-particles_rough_walls): on each z wall a square layer of fixed spheres of the radius
// touching it, spaced at least 2.1 radii (the number per period rounded down so the periodic x and y
// lengths hold whole numbers), moving with the wall's velocity; ids from firstId. Throws InputError
// when x or y is not periodic or z is.
std::vector<ParticleRecord> roughWallParticles(double radius, double density, const Config& c, std::int64_t firstId);

// Throws InputError for radius or density <= 0, non-finite values, duplicate ids, a sphere outside
// the domain, or two spheres overlapping by more than maxOverlap times their mean diameter.
void validateParticles(const std::vector<ParticleRecord>& p, const Config& c, double maxOverlap,
                       const std::string& source);

// The particles selected by the options (empty if none), validated.
std::vector<ParticleRecord> initialParticles(const ParticleConfig& pc, const Config& c);

} // namespace vp
