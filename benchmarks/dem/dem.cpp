// bench_dem: writes a vpsolve particle snapshot (particles_<step>.h5) as a LAMMPS 'dump custom'
// text file (id x y z vx vy vz) so that the shared front.py measures both codes the same way.
// usage: bench_dem particles_NNNNNN.h5 step > out.dump
#include <cstdio>
#include <cstdlib>
#include <hdf5.h>
#include <vector>

namespace {

bool readDataset(hid_t file, const char* name, hid_t type, void* out)
{
  hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
  if (ds < 0) return false;
  const herr_t err = H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out);
  H5Dclose(ds);
  return err >= 0;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 3) {
    std::fprintf(stderr, "usage: bench_dem particles_NNNNNN.h5 step > out.dump\n");
    return 2;
  }
  hid_t file = H5Fopen(argv[1], H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return 1;
  hid_t ds = H5Dopen2(file, "id", H5P_DEFAULT);
  hid_t space = H5Dget_space(ds);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  H5Sclose(space);
  H5Dclose(ds);
  std::vector<long long> id(n);
  std::vector<double> x(3 * n), v(3 * n);
  if (!readDataset(file, "id", H5T_NATIVE_LLONG, id.data()) || !readDataset(file, "position", H5T_NATIVE_DOUBLE, x.data()) ||
      !readDataset(file, "velocity", H5T_NATIVE_DOUBLE, v.data()))
    return 1;
  H5Fclose(file);
  std::printf("ITEM: TIMESTEP\n%s\nITEM: NUMBER OF ATOMS\n%llu\nITEM: ATOMS id x y z vx vy vz\n", argv[2],
              static_cast<unsigned long long>(n));
  for (hsize_t i = 0; i < n; ++i)
    std::printf("%lld %.10e %.10e %.10e %.6e %.6e %.6e\n", id[i], x[3 * i], x[3 * i + 1], x[3 * i + 2], v[3 * i],
                v[3 * i + 1], v[3 * i + 2]);
  return 0;
}
