#include "vp/io/ParticleWriter.hpp"
#include "vp/core/Error.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/io/RunRecord.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace vp {

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
  const std::string path = dir_ + "/" + h5::stepFile("particles", step);
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  if (file < 0) throw std::runtime_error("cannot create " + path);
  const hsize_t T = total, o = offset, m = n;
  h5::writeRows(file, "id", H5T_NATIVE_INT64, s.id.data(), T, o, m, 1);
  h5::writeRows(file, "radius", H5T_NATIVE_DOUBLE, radius.data(), T, o, m, 1);
  h5::writeRows(file, "position", H5T_NATIVE_DOUBLE, pos.data(), T, o, m, 3);
  h5::writeRows(file, "velocity", H5T_NATIVE_DOUBLE, vel.data(), T, o, m, 3);
  h5::writeRows(file, "angular_velocity", H5T_NATIVE_DOUBLE, omega.data(), T, o, m, 3);
  h5::writeRows(file, "force", H5T_NATIVE_DOUBLE, force.data(), T, o, m, 3);
  h5::writeRows(file, "orientation", H5T_NATIVE_DOUBLE, orient.data(), T, o, m, 4);
  h5::writeAttribute(file, "time", &time, 1);
  h5::writeAttribute(file, "vpsolve_run", runRecord());
  H5Fclose(file);

  snapshots_.push_back({step, time, total});
  if (rank == 0) writeXdmf();
}

std::vector<double> ParticleWriter::snapshotList() const
{
  std::vector<double> out;
  for (const Snapshot& s : snapshots_) out.insert(out.end(), {double(s.step), s.time, double(s.count)});
  return out;
}

void ParticleWriter::resume(const std::vector<double>& list)
{
  snapshots_.clear();
  for (std::size_t k = 0; k + 2 < list.size(); k += 3) {
    const int step = static_cast<int>(list[k]);
    if (std::ifstream(dir_ + "/" + h5::stepFile("particles", step))) snapshots_.push_back({step, list[k + 1], std::lround(list[k + 2])});
  }
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
      const std::string f = h5::stepFile("particles", sn.step);
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
    x.close();
    // A failed write (a full disk) keeps the previous index.
    if (!x) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp + " (disk full?); particles.xmf is kept as it was");
    }
  }
  std::rename(tmp.c_str(), (dir_ + "/particles.xmf").c_str());
}

} // namespace vp
