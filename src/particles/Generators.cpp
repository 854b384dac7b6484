#include "vp/particles/Generators.hpp"
#include "vp/core/Error.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/Packing.hpp"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <unordered_set>

namespace vp {

const char* const kParticleColumns[12] = {"id", "x", "y", "z", "radius", "density",
                                          "vx", "vy", "vz", "wx", "wy", "wz"};

namespace {

// Fills a record from the 12 column values (order of kParticleColumns).
ParticleRecord fromColumns(const double* v)
{
  ParticleRecord r;
  r.id = static_cast<std::int64_t>(v[0]);
  r.x = {v[1], v[2], v[3]};
  r.radius = v[4];
  r.density = v[5];
  r.v = {v[6], v[7], v[8]};
  r.w = {v[9], v[10], v[11]};
  return r;
}

void checkValues(const double* v, const std::string& where)
{
  for (int c = 0; c < 12; ++c)
    if (!std::isfinite(v[c]))
      failOption("-particles_file", where + ": column " + kParticleColumns[c] + " is not a finite number");
  if (v[0] < 0 || v[0] != std::floor(v[0]) || v[0] > 9.0e15)
    failOption("-particles_file", where + ": id must be an integer >= 0");
}

// The optional shape columns: aspect (1, a sphere, when absent) and the orientation qw,qx,qy,qz
// (normalised; the body z axis is a spheroid's symmetry axis).
const char* const kShapeColumns[5] = {"aspect", "qw", "qx", "qy", "qz"};

void setShape(ParticleRecord& r, const double* v, const bool* given, const std::string& where)
{
  if (given[0]) {
    if (!(v[0] > 0) || !std::isfinite(v[0])) failOption("-particles_file", where + ": aspect must be > 0, got " + formatNumber(v[0]));
    r.aspect.value = v[0];
  }
  if (given[1] || given[2] || given[3] || given[4]) {
    if (!(given[1] && given[2] && given[3] && given[4])) failOption("-particles_file", where + ": give all four of qw,qx,qy,qz");
    const double n = std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (!(n > 0) || !std::isfinite(n)) failOption("-particles_file", where + ": orientation qw,qx,qy,qz must be a non-zero quaternion");
    r.q = Quaternion{v[1] / n, v[2] / n, v[3] / n, v[4] / n};
  }
}

// Uniform double in [0, 1) from 53 random bits (same sequence on every platform).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

} // namespace

std::vector<ParticleRecord> readParticleCsv(const std::string& path)
{
  std::ifstream in(path);
  if (!in) failOption("-particles_file", "cannot open '" + path + "'");
  std::string line;
  if (!std::getline(in, line)) failOption("-particles_file", "'" + path + "' is empty (needs a header line)");
  std::vector<std::string> header;
  {
    std::stringstream h(line);
    std::string name;
    while (std::getline(h, name, ',')) {
      name.erase(std::remove_if(name.begin(), name.end(), [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }), name.end());
      header.push_back(name);
    }
  }
  int column[12];
  std::string missing;
  for (int c = 0; c < 12; ++c) {
    auto it = std::find(header.begin(), header.end(), kParticleColumns[c]);
    column[c] = it == header.end() ? -1 : static_cast<int>(it - header.begin());
    if (column[c] < 0) missing += std::string(missing.empty() ? "" : ",") + kParticleColumns[c];
  }
  if (!missing.empty())
    failOption("-particles_file", "'" + path + "' header lacks column(s) " + missing + " (needs id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz)");
  // Optional: fixed = 1 holds that particle (a rough wall of spheres), 0 leaves it free.
  const auto fixedIt = std::find(header.begin(), header.end(), "fixed");
  const long fixedColumn = fixedIt == header.end() ? -1 : fixedIt - header.begin();
  // Optional: shape = sphere or spheroid (a check of the aspect column), and the shape columns.
  const auto shapeIt = std::find(header.begin(), header.end(), "shape");
  const long shapeColumn = shapeIt == header.end() ? -1 : shapeIt - header.begin();
  long shapeCol[5];
  bool given[5];
  for (int c = 0; c < 5; ++c) {
    const auto it = std::find(header.begin(), header.end(), kShapeColumns[c]);
    shapeCol[c] = it == header.end() ? -1 : it - header.begin();
    given[c] = shapeCol[c] >= 0;
  }
  std::vector<ParticleRecord> out;
  std::vector<std::string> cells;
  long lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    cells.clear();
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    const std::string where = "'" + path + "' line " + std::to_string(lineNo);
    if (cells.size() != header.size())
      failOption("-particles_file", where + " has " + std::to_string(cells.size()) + " values, the header has " + std::to_string(header.size()));
    double v[12];
    for (int c = 0; c < 12; ++c) {
      const std::string& t = cells[column[c]];
      char* end = nullptr;
      v[c] = std::strtod(t.c_str(), &end);
      while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
      if (end == t.c_str() || (end && *end != 0))
        failOption("-particles_file", where + ": column " + kParticleColumns[c] + " value '" + t + "' is not a number");
    }
    checkValues(v, where);
    out.push_back(fromColumns(v));
    if (fixedColumn >= 0) {
      std::string t = cells[fixedColumn];
      t.erase(std::remove_if(t.begin(), t.end(), [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }), t.end());
      if (t != "0" && t != "1") failOption("-particles_file", where + ": column fixed must be 0 or 1, got '" + t + "'");
      if (t == "1") out.back().flags |= kFixed;
    }
    double sv[5] = {1, 1, 0, 0, 0};
    for (int c = 0; c < 5; ++c)
      if (given[c]) {
        char* end = nullptr;
        sv[c] = std::strtod(cells[shapeCol[c]].c_str(), &end);
        if (end == cells[shapeCol[c]].c_str())
          failOption("-particles_file", where + ": column " + kShapeColumns[c] + " value '" + cells[shapeCol[c]] + "' is not a number");
      }
    setShape(out.back(), sv, given, where);
    if (shapeColumn >= 0) {
      std::string t = cells[shapeColumn];
      t.erase(std::remove_if(t.begin(), t.end(), [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }), t.end());
      if (t != "sphere" && t != "spheroid") failOption("-particles_file", where + ": column shape must be sphere or spheroid, got '" + t + "'");
      if (t == "sphere" && out.back().aspect.value != 1) failOption("-particles_file", where + ": a sphere has aspect 1");
    }
  }
  return out;
}

std::vector<ParticleRecord> readParticleHdf5(const std::string& path)
{
  h5::QuietErrors quiet;  // report our own message instead of HDF5's trace
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::vector<std::vector<double>> col(12);
  std::string error;
  if (file < 0) error = "cannot open '" + path + "' as HDF5";
  for (int c = 0; c < 12 && error.empty(); ++c) {
    hsize_t rows = 0, cols = 0;
    error = h5::readTable(file, kParticleColumns[c], col[c], rows, cols);
    if (error.rfind("lacks", 0) == 0)
      error = "'" + path + "' lacks the dataset " + kParticleColumns[c] + " (needs 1-D datasets id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz)";
    else if (!error.empty())
      error = "'" + path + "' " + error;
    else if (cols != 1 || (c > 0 && rows != col[0].size()))
      error = "'" + path + "' dataset " + kParticleColumns[c] + " must be 1-D with one value per particle";
  }
  std::vector<double> shapeCol[5];
  bool given[5] = {};
  for (int c = 0; c < 5 && error.empty(); ++c) {
    hsize_t rows = 0, cols = 0;
    const std::string e = h5::readTable(file, kShapeColumns[c], shapeCol[c], rows, cols);
    given[c] = e.empty();
    if (given[c] && (cols != 1 || rows != col[0].size()))
      error = "'" + path + "' dataset " + kShapeColumns[c] + " must be 1-D with one value per particle";
  }
  if (file >= 0) H5Fclose(file);
  if (!error.empty()) failOption("-particles_file", error);
  std::vector<ParticleRecord> out;
  for (std::size_t i = 0; i < col[0].size(); ++i) {
    double v[12];
    for (int c = 0; c < 12; ++c) v[c] = col[c][i];
    checkValues(v, "'" + path + "' row " + std::to_string(i));
    out.push_back(fromColumns(v));
    double sv[5] = {1, 1, 0, 0, 0};
    for (int c = 0; c < 5; ++c)
      if (given[c]) sv[c] = shapeCol[c][i];
    setShape(out.back(), sv, given, "'" + path + "' row " + std::to_string(i));
  }
  return out;
}

std::vector<ParticleRecord> latticeParticles(const LatticeInput& in, double density)
{
  std::mt19937_64 rng(in.seed);
  const double amp = in.jitter * (0.5 * in.spacing - in.radius);
  int n[3];
  for (int d = 0; d < 3; ++d) n[d] = static_cast<int>(std::floor((in.hi[d] - in.lo[d]) / in.spacing + 1e-9));
  std::vector<ParticleRecord> out;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        ParticleRecord r;
        r.id = static_cast<std::int64_t>(out.size());
        r.radius = in.radius;
        r.density = density;
        const int idx[3] = {i, j, k};
        for (int d = 0; d < 3; ++d)
          r.x[d] = in.lo[d] + (idx[d] + 0.5) * in.spacing + amp * (2 * uniform(rng) - 1);
        out.push_back(r);
      }
  return out;
}

std::vector<ParticleRecord> roughWallParticles(double radius, double density, const Config& c, std::int64_t firstId)
{
  const char* opt = "-particles_rough_walls";
  if (!c.bc.periodic(0) || !c.bc.periodic(1) || c.bc.periodic(2))
    failOption(opt, "a layer of fixed spheres on each z wall needs walls along z and periodic x and y");
  int n[2];
  double spacing[2];
  for (int d = 0; d < 2; ++d) {
    const double length = c.grid.hi[d] - c.grid.lo[d];
    // A clearance of 5 % of the diameter between neighbours: no contacts within the layer.
    n[d] = static_cast<int>(std::floor(length / (2.1 * radius)));
    if (n[d] < 1) failOption(opt, std::string("the radius ") + formatNumber(radius) + " m leaves no sphere across the period along " + "xy"[d]);
    spacing[d] = length / n[d];
  }
  std::vector<ParticleRecord> out;
  for (int side = 0; side < 2; ++side) {
    const int face = 4 + side;
    const double z = side == 0 ? c.grid.lo[2] + radius : c.grid.hi[2] - radius;
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        ParticleRecord r;
        r.id = firstId + static_cast<std::int64_t>(out.size());
        r.radius = radius;
        r.density = density;
        r.x = {c.grid.lo[0] + (i + 0.5) * spacing[0], c.grid.lo[1] + (j + 0.5) * spacing[1], z};
        r.v = c.bc.type[face] == BcType::Velocity ? c.bc.velocity[face] : Vec3{};
        r.flags = kFixed;
        out.push_back(r);
      }
  }
  return out;
}

std::vector<ParticleRecord> randomParticles(const RandomInput& in, double density)
{
  const double a = in.radius, s = in.radiusSpread, aMax = a * (1 + s);
  Vec3 size = in.hi - in.lo;
  const double volume = size.x * size.y * size.z;
  // Radii uniform in [a (1 - s), a (1 + s)] have a mean cube of a^3 (1 + s^2).
  const auto target = static_cast<std::size_t>(std::llround(in.volumeFraction * volume / (4.0 / 3.0 * M_PI * a * a * a * (1 + s * s))));
  std::mt19937_64 rng(in.seed);
  std::vector<double> radius(target, a);
  if (s > 0) {  // drawn first and placed largest first, so that the placement does not favour the small ones
    for (double& r : radius) r = a * (1 + s * (2 * uniform(rng) - 1));
    std::sort(radius.begin(), radius.end(), std::greater<>());
  }
  // Random sequential addition on a grid of cells of the largest diameter: candidates overlap only
  // spheres in the 27 surrounding cells.
  int n[3];
  for (int d = 0; d < 3; ++d) n[d] = std::max(1, static_cast<int>(size[d] / (2 * aMax)));
  std::vector<std::vector<std::size_t>> cell(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  auto cellOf = [&](const Vec3& p, int d) {
    return std::min(n[d] - 1, std::max(0, static_cast<int>((p[d] - in.lo[d]) / size[d] * n[d])));
  };
  std::vector<ParticleRecord> out;
  const std::size_t maxAttempts = 2000 * target + 1000;
  for (std::size_t attempt = 0; attempt < maxAttempts && out.size() < target; ++attempt) {
    const double r = radius[out.size()];
    Vec3 p;
    for (int d = 0; d < 3; ++d) p[d] = in.lo[d] + r + (size[d] - 2 * r) * uniform(rng);
    const int c[3] = {cellOf(p, 0), cellOf(p, 1), cellOf(p, 2)};
    bool free = true;
    for (int dz = -1; dz <= 1 && free; ++dz)
      for (int dy = -1; dy <= 1 && free; ++dy)
        for (int dx = -1; dx <= 1 && free; ++dx) {
          const int x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) continue;
          for (std::size_t j : cell[x + n[0] * (y + static_cast<std::size_t>(n[1]) * z)])
            if (norm(out[j].x - p) < r + out[j].radius) { free = false; break; }
        }
    if (!free) continue;
    cell[c[0] + n[0] * (c[1] + static_cast<std::size_t>(n[1]) * c[2])].push_back(out.size());
    ParticleRecord rec;
    rec.id = static_cast<std::int64_t>(out.size());
    rec.radius = r;
    rec.density = density;
    rec.x = p;
    out.push_back(rec);
  }
  if (out.size() < target)
    failOption("-particles_random", "reached only " + std::to_string(out.size()) + " of " + std::to_string(target) +
                                  " particles; lower the volume fraction");
  return out;
}

void validateParticles(const std::vector<ParticleRecord>& p, const Config& c, double maxOverlap, const std::string& option)
{
  std::unordered_set<std::int64_t> ids;
  const char* axis = "xyz";
  for (const ParticleRecord& r : p) {
    const std::string who = "particle " + std::to_string(r.id);
    if (!ids.insert(r.id).second) failOption(option, "duplicate particle id " + std::to_string(r.id));
    if (!(r.radius > 0)) failOption(option, who + ": radius must be > 0, got " + formatNumber(r.radius));
    if (!(r.density > 0)) failOption(option, who + ": density must be > 0, got " + formatNumber(r.density));
    for (int d = 0; d < 3; ++d) {
      const double lo = c.grid.lo[d], hi = c.grid.hi[d];
      // On a wall axis the particle must fit (up to the overlap tolerance); on a periodic one the centre.
      Vec3 e;
      e[d] = 1;
      const double half = r.aspect.value == 1 ? r.radius : Shape{r.radius, r.aspect.value}.extent(toBody(r.q, e));
      const double margin = c.bc.periodic(d) ? 0 : half - 2 * maxOverlap * r.radius;
      if (!(r.x[d] >= lo + margin && r.x[d] <= hi - margin) || (c.bc.periodic(d) && r.x[d] == hi))
        failOption(option, who + " at " + axis[d] + " = " + formatNumber(r.x[d]) + " lies outside the domain [" + formatNumber(lo) + ", " +
                         formatNumber(hi) + "] (half-width " + formatNumber(half) + " along it)");
    }
  }
  if (p.empty()) return;
  double rmax = 0;
  Vec3 lo{c.grid.lo[0], c.grid.lo[1], c.grid.lo[2]}, hi{c.grid.hi[0], c.grid.hi[1], c.grid.hi[2]};
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    rmax = std::max(rmax, Shape{p[i].radius, p[i].aspect.value}.boundingRadius());
    x[i] = p[i].x;
  }
  CellBuckets buckets;
  buckets.build(x, x.size(), lo, hi, 2 * rmax);
  auto check = [&](const ParticleRecord& a, const ParticleRecord& b, const Vec3& shift) {
    const Vec3 d = b.x + shift - a.x;
    const double overlap = a.aspect.value == 1 && b.aspect.value == 1
                             ? a.radius + b.radius - norm(d)
                             : -closestPoints({a.radius, a.aspect.value}, a.q, {b.radius, b.aspect.value}, b.q, d, d).gap;
    if (overlap > maxOverlap * (a.radius + b.radius))
      failOption(option, "particles " + std::to_string(a.id) + " and " + std::to_string(b.id) + " overlap by " + formatNumber(overlap) +
                       " m, more than -particles_max_overlap " + formatNumber(maxOverlap) + " of their mean diameter");
  };
  buckets.forEachCandidate(p.size(), [&](std::size_t i, std::size_t j) { check(p[i], p[j], {}); });
  // Pairs across periodic faces: compare the spheres near a periodic face with the shifted others.
  for (int d = 0; d < 3; ++d) {
    if (!c.bc.periodic(d)) continue;
    const double L = hi[d] - lo[d];
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p[i].x[d] > lo[d] + 2 * rmax) continue;
      for (std::size_t j = 0; j < p.size(); ++j) {
        if (p[j].x[d] < hi[d] - 2 * rmax || i == j) continue;
        Vec3 s;
        s[d] = -L;
        check(p[i], p[j], s);
      }
    }
  }
}

namespace {

// Generated spheroids (-particle_shape spheroid): the generator places their bounding spheres (so
// none overlap, whatever the orientations), then each becomes a spheroid of the given equatorial
// radius, aligned with -particle_axis or, with -particle_orientation random, turned uniformly.
// A random packing's fraction is the spheroids': its bounding spheres' is larger by bound^3 / aspect.
double boundOverEquator(const ParticleConfig& pc) { return Shape{1.0, pc.aspect}.boundingRadius(); }

LatticeInput bounding(LatticeInput in, const ParticleConfig& pc)
{
  in.radius *= boundOverEquator(pc);
  return in;
}

RandomInput bounding(RandomInput in, const ParticleConfig& pc)
{
  const double b = boundOverEquator(pc);
  in.radius *= b;
  in.volumeFraction *= b * b * b / pc.aspect;
  return in;
}

std::vector<ParticleRecord> spheroids(std::vector<ParticleRecord> p, const ParticleConfig& pc, std::uint64_t seed)
{
  std::mt19937_64 rng(seed + 1);
  std::normal_distribution<double> gauss;
  for (ParticleRecord& r : p) {
    r.radius /= boundOverEquator(pc);
    r.aspect.value = pc.aspect;
    Vec3 axis = pc.axis;
    while (pc.randomAxes) {  // isotropic: a uniform direction
      axis = {gauss(rng), gauss(rng), gauss(rng)};
      if (norm(axis) > 1e-3) break;
    }
    r.q = alignedWith(axis / norm(axis));
  }
  return p;
}

} // namespace

std::vector<ParticleRecord> initialParticles(const ParticleConfig& pc, const Config& c)
{
  std::vector<ParticleRecord> p;
  std::string option;
  if (!pc.file.empty()) {
    const std::string& f = pc.file;
    const bool h5 = f.size() > 3 && (f.compare(f.size() - 3, 3, ".h5") == 0 || (f.size() > 5 && f.compare(f.size() - 5, 5, ".hdf5") == 0));
    p = h5 ? readParticleHdf5(f) : readParticleCsv(f);
    option = "-particles_file";
  } else if (pc.lattice.set) {
    p = pc.spheroid ? spheroids(latticeParticles(bounding(pc.lattice, pc), pc.density), pc, pc.lattice.seed) : latticeParticles(pc.lattice, pc.density);
    option = "-particles_lattice";
  } else if (pc.random.set) {
    p = pc.spheroid ? spheroids(randomParticles(bounding(pc.random, pc), pc.density), pc, pc.random.seed) : randomParticles(pc.random, pc.density);
    option = "-particles_random";
  } else if (pc.packed.set) {
    std::array<bool, 3> wrap{};
    for (int d = 0; d < 3; ++d)  // periodic where the box spans the domain
      wrap[d] = c.bc.periodic(d) && pc.packed.lo[d] <= c.grid.lo[d] && pc.packed.hi[d] >= c.grid.hi[d];
    p = packedParticles(pc.packed, pc.density, wrap, pc.contact.roughness);
    option = "-particles_packed";
  } else if (pc.single.set) {
    ParticleRecord r;
    r.id = 0;
    r.radius = pc.radius;
    r.density = pc.density;
    r.x = pc.single.position;
    r.v = pc.single.velocity;
    r.w = pc.single.angularVelocity;
    r.flags = pc.single.fixed ? kFixed : 0;  // held in place; its velocities are a prescribed motion
    r.aspect.value = pc.aspect;
    r.q = alignedWith(pc.axis / norm(pc.axis));
    p.push_back(r);
    option = "-particle_position";
  }
  if (pc.allFixed)
    for (ParticleRecord& r : p) r.flags |= kFixed;
  validateParticles(p, c, pc.maxOverlap, option);
  if (pc.roughWalls > 0) {
    std::int64_t next = 0;
    for (const ParticleRecord& r : p) next = std::max(next, r.id + 1);
    const std::vector<ParticleRecord> walls = roughWallParticles(pc.roughWalls, pc.density, c, next);
    p.insert(p.end(), walls.begin(), walls.end());
    validateParticles(p, c, pc.maxOverlap, "-particles_rough_walls");
  }
  return p;
}

} // namespace vp
