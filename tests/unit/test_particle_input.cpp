// Particle input: generators (lattice, random packing) and the CSV and HDF5 readers, and the
// validation that rejects bad particles with a message naming the problem.
#include "../support/DemFixtures.hpp"
#include "vp/core/Error.hpp"
#include "vp/particles/Generators.hpp"
#include "vp/particles/Packing.hpp"
#include "vp/particles/Shape.hpp"
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <hdf5.h>
#include <unistd.h>

using namespace vp;
using namespace vp::test;

namespace {

double minDistanceRatio(const std::vector<ParticleRecord>& p)  // min |x_i - x_j| / (a_i + a_j)
{
  double m = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) m = std::min(m, norm(p[i].x - p[j].x) / (p[i].radius + p[j].radius));
  return m;
}

// Under the test's working folder (the build tree).
std::string tempPath(const char* name) { return "scratch_particle_input_" + std::to_string(getpid()) + "_" + name; }

// A 5 cm box filled to 0.25 with spheres of 2 mm radius (seed 9).
RandomInput randomBox()
{
  RandomInput in;
  in.set = true;
  in.lo = {0, 0, 0};
  in.hi = {0.05, 0.05, 0.05};
  in.volumeFraction = 0.25;
  in.radius = 0.002;
  in.seed = 9;
  return in;
}

} // namespace

TEST_CASE("Lattice generator: count, no overlap, inside the box, reproducible by seed", "[dem]")
{
  LatticeInput in;
  in.set = true;
  in.lo = {0, 0, 0};
  in.hi = {0.1, 0.05, 0.03};
  in.spacing = 0.01;
  in.radius = 0.004;
  in.jitter = 1;
  in.seed = 3;
  const auto p = latticeParticles(in, 1500);
  REQUIRE(p.size() == 10 * 5 * 3);
  CHECK(minDistanceRatio(p) >= 1);
  for (const auto& r : p)
    for (int d = 0; d < 3; ++d) CHECK((r.x[d] - r.radius >= in.lo[d] && r.x[d] + r.radius <= in.hi[d]));
  const auto again = latticeParticles(in, 1500);
  CHECK(again[17].x.x == p[17].x.x);
  in.seed = 4;
  CHECK(latticeParticles(in, 1500)[17].x.x != p[17].x.x);
}

TEST_CASE("Random packing: target volume fraction, no overlap, reproducible by seed", "[dem]")
{
  RandomInput in = randomBox();
  const auto p = randomParticles(in, 2500);
  const double v = 4.0 / 3.0 * M_PI * std::pow(in.radius, 3);
  CHECK(std::fabs(p.size() * v / 1.25e-4 - 0.25) < v / 1.25e-4);
  CHECK(minDistanceRatio(p) >= 1);
  for (const auto& r : p)
    for (int d = 0; d < 3; ++d) CHECK((r.x[d] >= r.radius && r.x[d] <= 0.05 - r.radius));
  CHECK(randomParticles(in, 2500)[100].x.y == p[100].x.y);
  in.volumeFraction = 0.35;  // within the option's range but beyond what this small box takes
  in.hi = {0.009, 0.009, 0.009};
  CHECK_THROWS_WITH(randomParticles(in, 2500), Catch::Contains("-particles_random") && Catch::Contains("lower the volume fraction"));
}

TEST_CASE("Random packing with a radius spread: radii uniform in the band, the volume fraction, no overlap", "[dem]")
{
  RandomInput in = randomBox();
  in.radiusSpread = 0.2;
  const auto p = randomParticles(in, 2500);
  double solid = 0, lo = HUGE_VAL, hi = 0, below = 0;
  for (const auto& r : p) {
    solid += 4.0 / 3.0 * M_PI * std::pow(r.radius, 3);
    lo = std::min(lo, r.radius);
    hi = std::max(hi, r.radius);
    below += r.radius < in.radius;
    for (int d = 0; d < 3; ++d) CHECK((r.x[d] >= r.radius && r.x[d] <= 0.05 - r.radius));
  }
  CHECK(p.size() > 400);
  CHECK(std::fabs(solid / 1.25e-4 - 0.25) < 0.005);  // the mean cube a^3 (1 + s^2) sets the count
  CHECK((lo >= 0.0016 && lo < 0.00162 && hi <= 0.0024 && hi > 0.00238));
  CHECK(std::fabs(below / p.size() - 0.5) < 0.08);  // uniform: half below the nominal radius
  CHECK(minDistanceRatio(p) >= 1);
  CHECK(p.front().radius >= p.back().radius);  // placed largest first
  in.radiusSpread = 0;  // no spread: the monodisperse packing of the same seed
  const auto mono = randomParticles(in, 2500);
  for (const auto& r : mono) CHECK(r.radius == in.radius);
}

TEST_CASE("Generated spheroids: a lattice's and random ones, aligned or isotropic, at the volume fraction, apart", "[dem][shape]")
{
  Config c = boxConfig({0, 0, 0}, {0.05, 0.05, 0.05}, {4, 4, 4});
  ParticleConfig pc;
  pc.density = 2000;
  pc.spheroid = true;
  pc.aspect = 2;
  pc.axis = {1, 1, 0};
  auto apart = [](const std::vector<ParticleRecord>& p) {  // the least gap between two surfaces
    double m = HUGE_VAL;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        const Vec3 d = p[j].x - p[i].x;
        m = std::min(m, closestPoints({p[i].radius, p[i].aspect.value}, p[i].q, {p[j].radius, p[j].aspect.value}, p[j].q, d, d).gap);
      }
    return m;
  };
  SECTION("lattice, aligned")
  {
    pc.lattice = {true, {0, 0, 0}, {0.05, 0.05, 0.05}, 0.01, 0.0024, 1, 7};
    const std::vector<ParticleRecord> p = initialParticles(pc, c);
    REQUIRE(p.size() == 125);
    for (const ParticleRecord& r : p) {
      CHECK(r.radius == 0.0024);
      CHECK(r.aspect.value == 2);
      CHECK(norm(toSpace(r.q, {0, 0, 1}) - Vec3{1, 1, 0} / std::sqrt(2.0)) < 1e-14);
    }
    CHECK(apart(p) > 0);
  }
  SECTION("random, isotropic")
  {
    pc.random = {true, {0, 0, 0}, {0.05, 0.05, 0.05}, 0.06, 0.0015, 5};
    pc.randomAxes = true;
    const std::vector<ParticleRecord> p = initialParticles(pc, c);
    const double v = Shape{0.0015, 2}.volume();
    CHECK(std::fabs(p.size() * v / 1.25e-4 - 0.06) < v / 1.25e-4);
    double meanAz = 0;
    for (const ParticleRecord& r : p) meanAz += std::fabs(toSpace(r.q, {0, 0, 1}).z) / p.size();
    INFO(p.size() << " spheroids, mean |axis . z| " << meanAz);
    CHECK(std::fabs(meanAz - 0.5) < 3 * 0.29 / std::sqrt(double(p.size())));  // uniform on [0, 1]: sd 0.29
    CHECK(apart(p) > 0);
  }
}

TEST_CASE("Dense packing: solid fraction beyond random addition, no contact, periodic images, bidisperse", "[dem]")
{
  PackedInput in;
  in.set = true;
  in.lo = {0, 0, 0};
  in.hi = {0.006, 0.006, 0.008};
  in.radius = 5e-4;
  in.volumeFraction = 0.5;
  in.seed = 2;
  const double clearance = 0.01, volume = 0.006 * 0.006 * 0.008;
  auto ball = [](double r) { return 4.0 / 3.0 * M_PI * r * r * r; };
  // Periodic along x and y (a shear cell), walls along z: gaps by the nearest image.
  auto smallestGap = [&](const std::vector<ParticleRecord>& p) {
    double m = HUGE_VAL;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        Vec3 d = p[i].x - p[j].x;
        for (int a = 0; a < 2; ++a) d[a] -= 0.006 * std::round(d[a] / 0.006);
        m = std::min(m, norm(d) / (p[i].radius + p[j].radius) - 1);
      }
    return m;
  };
  const auto p = packedParticles(in, 1000, {true, true, false}, clearance);
  double solid = 0;
  for (const auto& r : p) {
    solid += ball(r.radius);
    CHECK((r.x.z >= r.radius && r.x.z <= 0.008 - r.radius));
    CHECK((r.x.x >= 0 && r.x.x < 0.006));
  }
  CHECK(std::fabs(solid / volume - 0.5) < ball(in.radius) / volume);
  CHECK(smallestGap(p) >= clearance);
  CHECK(packedParticles(in, 1000, {true, true, false}, clearance)[50].x.x == p[50].x.x);

  in.sizeRatio = 1.4;  // equal volumes of both sizes
  const auto two = packedParticles(in, 1000, {true, true, false}, clearance);
  double large = 0, small = 0;
  for (const auto& r : two) (r.radius > in.radius ? large : small) += ball(r.radius);
  CHECK(std::fabs(large / small - 1) < 0.1);
  CHECK(smallestGap(two) >= clearance);

  in.sizeRatio = 1;
  in.volumeFraction = 0.6;  // in the option's range, but a box of two diameters with walls jams
  in.hi = {0.002, 0.002, 0.002};
  CHECK_THROWS_WITH(packedParticles(in, 1000, {false, false, false}, clearance),
                    Catch::Contains("-particles_packed") && Catch::Contains("lower the volume fraction"));
}

TEST_CASE("CSV and HDF5 particle tables read the same particles", "[dem]")
{
  const std::string csv = tempPath("p.csv"), h5 = tempPath("p.h5");
  {
    std::ofstream f(csv);
    f << "x,id,y,z,radius,density,vx,vy,vz,wx,wy,wz,colour\n"  // any column order, extra columns
      << "0.1,5,0.2,0.3,0.01,1000,1,2,3,4,5,6,red\n"
      << "0.4,2,0.5,0.6,0.02,2000,-1,-2,-3,-4,-5,-6,blue\n";
  }
  const double cols[12][2] = {{5, 2}, {0.1, 0.4}, {0.2, 0.5}, {0.3, 0.6}, {0.01, 0.02}, {1000, 2000},
                              {1, -1}, {2, -2}, {3, -3}, {4, -4}, {5, -5}, {6, -6}};
  {
    hid_t file = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hsize_t n = 2;
    for (int c = 0; c < 12; ++c) {
      hid_t space = H5Screate_simple(1, &n, nullptr);
      hid_t ds = H5Dcreate2(file, kParticleColumns[c], H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, cols[c]);
      H5Dclose(ds);
      H5Sclose(space);
    }
    H5Fclose(file);
  }
  const auto a = readParticleCsv(csv), b = readParticleHdf5(h5);
  REQUIRE(a.size() == 2);
  REQUIRE(b.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(a[i].id == b[i].id);
    CHECK(a[i].radius == b[i].radius);
    CHECK(a[i].density == b[i].density);
    for (int d = 0; d < 3; ++d) CHECK((a[i].x[d] == b[i].x[d] && a[i].v[d] == b[i].v[d] && a[i].w[d] == b[i].w[d]));
  }
  CHECK(a[1].id == 2);
  CHECK(a[1].w.z == -6);
  {
    hid_t file = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    H5Fclose(file);
  }
  CHECK_THROWS_WITH(readParticleHdf5(h5), Catch::Contains("lacks the dataset id"));
  std::remove(csv.c_str());
  std::remove(h5.c_str());
}

TEST_CASE("CSV: an optional fixed column holds the particles marked 1 and rejects other values", "[dem]")
{
  const std::string csv = tempPath("fixed.csv");
  auto write = [&](const char* third) {
    std::ofstream f(csv);
    f << "id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,fixed\n"
      << "0,0.1,0.1,0.1,0.01,1000,0,0,0,0,0,0,1\n"
      << "1,0.2,0.1,0.1,0.01,1000,0,0,0,0,0,0, 0\n"
      << "2,0.3,0.1,0.1,0.01,1000,0,0,0,0,0,0," << third << "\n";
  };
  write("1");
  const auto p = readParticleCsv(csv);
  REQUIRE(p.size() == 3);
  CHECK(p[0].flags == kFixed);
  CHECK(p[1].flags == 0);
  CHECK(p[2].flags == kFixed);
  write("0.5");
  CHECK_THROWS_WITH(readParticleCsv(csv), Catch::Contains("line 4: column fixed must be 0 or 1, got '0.5'"));
  std::remove(csv.c_str());
}

TEST_CASE("Particle tables: optional shape columns (aspect, orientation) in CSV and HDF5; absent ones give spheres", "[dem][shape]")
{
  const std::string csv = tempPath("shape.csv"), h5 = tempPath("shape.h5");
  {
    std::ofstream f(csv);
    f << "id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,shape,aspect,qw,qx,qy,qz\n"
      << "0,0.1,0.1,0.1,0.01,1000,0,0,0,0,0,0,spheroid,2.5,2,0,2,0\n"  // normalised on reading
      << "1,0.3,0.1,0.1,0.01,1000,0,0,0,0,0,0,sphere,1,1,0,0,0\n";
  }
  const auto p = readParticleCsv(csv);
  REQUIRE(p.size() == 2);
  CHECK(p[0].aspect.value == 2.5);
  CHECK(p[0].q.w == Approx(std::sqrt(0.5)));
  CHECK(p[0].q.y == Approx(std::sqrt(0.5)));
  CHECK(p[1].aspect.value == 1);
  {
    hid_t file = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hsize_t n = 1;
    auto put = [&](const char* name, double v) {
      hid_t space = H5Screate_simple(1, &n, nullptr);
      hid_t ds = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &v);
      H5Dclose(ds);
      H5Sclose(space);
    };
    const double row[12] = {4, 0.1, 0.2, 0.3, 0.01, 1000, 0, 0, 0, 0, 0, 0};
    for (int c = 0; c < 12; ++c) put(kParticleColumns[c], row[c]);
    put("aspect", 0.5);
    H5Fclose(file);
  }
  const auto q = readParticleHdf5(h5);
  REQUIRE(q.size() == 1);
  CHECK(q[0].aspect.value == 0.5);
  CHECK(q[0].q.w == 1);  // no orientation columns: the body frame is the space frame
  {
    std::ofstream f(csv);
    f << "id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,aspect,qw\n0,0.1,0.1,0.1,0.01,1000,0,0,0,0,0,0,-1,1\n";
  }
  CHECK_THROWS_WITH(readParticleCsv(csv), Catch::Contains("line 2: aspect must be > 0, got -1"));
  {
    std::ofstream f(csv);
    f << "id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,aspect,qw\n0,0.1,0.1,0.1,0.01,1000,0,0,0,0,0,0,2,1\n";
  }
  CHECK_THROWS_WITH(readParticleCsv(csv), Catch::Contains("line 2: give all four of qw,qx,qy,qz"));
  std::remove(csv.c_str());
  std::remove(h5.c_str());
}

TEST_CASE("Particle validation names the problem", "[dem]")
{
  Config c = boxConfig({0, 0, 0}, {0.1, 0.1, 0.1}, {4, 4, 4});
  auto fails = [&](std::vector<ParticleRecord> p, const char* what) {
    INFO(what);
    CHECK_THROWS_AS(validateParticles(p, c, 0.01, "-particles_file"), InputError);
    CHECK_THROWS_WITH(validateParticles(p, c, 0.01, "-particles_file"), Catch::Contains(what));
  };
  const ParticleRecord ok = sphere(1, {0.05, 0.05, 0.05}, 0.01, 1000);
  fails({ok, sphere(2, {0.069, 0.05, 0.05}, 0.01, 1000)}, "overlap");
  fails({sphere(1, {0.005, 0.05, 0.05}, 0.01, 1000)}, "outside the domain");
  fails({sphere(1, {0.05, 0.05, 0.05}, 0, 1000)}, "radius must be > 0");
  fails({sphere(1, {0.05, 0.05, 0.05}, 0.01, -1)}, "density must be > 0");
  fails({ok, sphere(1, {0.08, 0.05, 0.05}, 0.01, 1000)}, "duplicate particle id 1");
  // Touching within the tolerance, and overlapping across a periodic face.
  CHECK_NOTHROW(validateParticles({ok, sphere(2, {0.0699, 0.05, 0.05}, 0.01, 1000)}, c, 0.01, "-particles_file"));
  c.bc.type[0] = c.bc.type[1] = BcType::Periodic;
  fails({sphere(1, {0.005, 0.05, 0.05}, 0.01, 1000), sphere(2, {0.09, 0.05, 0.05}, 0.01, 1000)}, "overlap");
}
