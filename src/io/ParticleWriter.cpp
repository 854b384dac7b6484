#include "vp/io/ParticleWriter.hpp"
#include "vp/core/Error.hpp"
#include <cstdio>
#include <fstream>
#include <hdf5.h>
#include <stdexcept>

namespace vp {

namespace {

std::string snapshotName(int step)
{
  char name[64];
  std::snprintf(name, sizeof name, "particles_%06d.h5", step);
  return name;
}

// Writes this rank's rows [offset, offset + n) of a global N x cols dataset, collectively.
void writeRows(hid_t file, const char* name, hid_t type, const void* data, hsize_t total, hsize_t offset, hsize_t n,
               hsize_t cols)
{
  const int rank = cols > 1 ? 2 : 1;
  hsize_t dims[2] = {total, cols}, start[2] = {offset, 0}, count[2] = {n, cols};
  hid_t fspace = H5Screate_simple(rank, dims, nullptr);
  hid_t ds = H5Dcreate2(file, name, type, fspace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hid_t mspace = H5Screate_simple(rank, count, nullptr);
  if (n > 0)
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
  else {
    H5Sselect_none(fspace);
    H5Sselect_none(mspace);
  }
  hid_t xfer = H5Pcreate(H5P_DATASET_XFER);
  H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE);
  const herr_t err = H5Dwrite(ds, type, mspace, fspace, xfer, data);
  H5Pclose(xfer);
  H5Sclose(mspace);
  H5Dclose(ds);
  H5Sclose(fspace);
  if (err < 0) throw std::runtime_error(std::string("HDF5: cannot write dataset ") + name);
}

} // namespace

ParticleWriter::ParticleWriter(MPI_Comm comm, std::string dir) : comm_(comm), dir_(std::move(dir)) {}

void ParticleWriter::write(const ParticleStore& s, int step, double time)
{
  const long n = static_cast<long>(s.nOwned);
  long offset = 0, total = 0;
  MPI_Exscan(&n, &offset, 1, MPI_LONG, MPI_SUM, comm_);
  MPI_Allreduce(&n, &total, 1, MPI_LONG, MPI_SUM, comm_);
  int rank;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0) offset = 0;

  std::vector<double> radius(n), pos(3 * n), vel(3 * n), omega(3 * n), force(3 * n), orient(4 * n);
  for (long i = 0; i < n; ++i) {
    radius[i] = s.radius[i];
    const Vec3 f = s.force[i] + s.fhyd[i];
    for (int d = 0; d < 3; ++d) {
      pos[3 * i + d] = s.x[i][d];
      vel[3 * i + d] = s.v[i][d];
      omega[3 * i + d] = s.w[i][d];
      force[3 * i + d] = f[d];
    }
    const Quaternion& q = s.q[i];
    orient[4 * i] = q.w;
    orient[4 * i + 1] = q.x;
    orient[4 * i + 2] = q.y;
    orient[4 * i + 3] = q.z;
  }

  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, comm_, MPI_INFO_NULL);
  const std::string path = dir_ + "/" + snapshotName(step);
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  if (file < 0) throw std::runtime_error("cannot create " + path);
  const hsize_t T = total, o = offset, m = n;
  writeRows(file, "id", H5T_NATIVE_INT64, s.id.data(), T, o, m, 1);
  writeRows(file, "radius", H5T_NATIVE_DOUBLE, radius.data(), T, o, m, 1);
  writeRows(file, "position", H5T_NATIVE_DOUBLE, pos.data(), T, o, m, 3);
  writeRows(file, "velocity", H5T_NATIVE_DOUBLE, vel.data(), T, o, m, 3);
  writeRows(file, "angular_velocity", H5T_NATIVE_DOUBLE, omega.data(), T, o, m, 3);
  writeRows(file, "force", H5T_NATIVE_DOUBLE, force.data(), T, o, m, 3);
  writeRows(file, "orientation", H5T_NATIVE_DOUBLE, orient.data(), T, o, m, 4);
  hid_t aspace = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, aspace, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &time);
  H5Aclose(attr);
  H5Sclose(aspace);
  H5Fclose(file);

  snapshots_.push_back({step, time, total});
  if (rank == 0) writeXdmf();
}

void ParticleWriter::writeXdmf() const
{
  const std::string tmp = dir_ + "/particles.xmf.tmp";
  {
    std::ofstream x(tmp);
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const Snapshot& sn : snapshots_) {
      if (sn.count == 0) continue;
      const std::string f = snapshotName(sn.step);
      const std::string N = std::to_string(sn.count);
      auto item = [&](const char* name, const char* dims, const char* type, int prec) {
        x << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\"" << prec
          << "\" Format=\"HDF\">" << f << ":/" << name << "</DataItem>\n";
      };
      auto attribute = [&](const char* name, const char* kind, int cols) {
        x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"Node\">\n";
        const std::string dims = cols > 1 ? N + " " + std::to_string(cols) : N;
        item(name, dims.c_str(), "Float", 8);
        x << "    </Attribute>\n";
      };
      x << "   <Grid Name=\"particles_" << sn.step << "\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << sn.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << N << "\"/>\n"
        << "    <Geometry GeometryType=\"XYZ\">\n";
      item("position", (N + " 3").c_str(), "Float", 8);
      x << "    </Geometry>\n";
      x << "    <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item("id", N.c_str(), "Int", 8);
      x << "    </Attribute>\n";
      attribute("radius", "Scalar", 1);
      attribute("velocity", "Vector", 3);
      attribute("angular_velocity", "Vector", 3);
      attribute("force", "Vector", 3);
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  }
  std::rename(tmp.c_str(), (dir_ + "/particles.xmf").c_str());
}

} // namespace vp
