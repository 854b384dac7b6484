#include "vp/io/ParticleWriter.hpp"
#include "vp/core/Error.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/io/RunRecord.hpp"
#include "vp/particles/ParticleFields.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

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

  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, comm_, MPI_INFO_NULL);
  const std::string path = dir_ + "/" + h5::stepFile("particles", step);
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  if (file < 0) throw std::runtime_error("cannot create " + path);
  const hsize_t T_ = total, o = offset, m = n;
  // The kSnapshot fields of ParticleFields.hpp as they are, then two derived quantities: the total
  // force (contact + hydrodynamic) and the symmetry axis.
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo& info, auto sync) {
    if constexpr ((decltype(sync)::value & kSnapshot) != 0) {
      using T = typename std::remove_reference_t<decltype(s.*field)>::value_type;
      if constexpr (std::is_same_v<T, std::int64_t>) {
        h5::writeRows(file, info.snapshot, H5T_NATIVE_INT64, (s.*field).data(), T_, o, m, 1);
      } else {
        const int w = doublesOf<T>();
        std::vector<double> rows(w * n);
        double* p = rows.data();
        for (long i = 0; i < n; ++i) writeDoubles((s.*field)[i], p);
        h5::writeRows(file, info.snapshot, H5T_NATIVE_DOUBLE, rows.data(), T_, o, m, w);
      }
    }
  });
  std::vector<double> force(3 * n);
  double* p = force.data();
  for (long i = 0; i < n; ++i) writeDoubles(s.force[i] + s.fhyd[i], p);
  h5::writeRows(file, "force", H5T_NATIVE_DOUBLE, force.data(), T_, o, m, 3);
  // The symmetry axis (body z) in space: a ParaView glyph oriented by it shows a spheroid's attitude.
  p = force.data();
  for (long i = 0; i < n; ++i) writeDoubles(toSpace(s.q[i], Vec3{0, 0, 1}), p);
  h5::writeRows(file, "axis", H5T_NATIVE_DOUBLE, force.data(), T_, o, m, 3);
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
      // From the kSnapshot fields: the position is the geometry, scalars and vectors are attributes
      // (XDMF has no quaternion type: the orientation stays in the HDF5 file).
      forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto, const ParticleFieldInfo& info, auto sync) {
        constexpr unsigned flags = decltype(sync)::value;
        if constexpr ((flags & kSnapshot) != 0 && (flags & kShift) != 0) item(info.snapshot, (N + " 3").c_str(), "Float", 8);
      });
      x << "    </Geometry>\n";
      forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo& info, auto sync) {
        constexpr unsigned flags = decltype(sync)::value;
        using T = typename std::remove_reference_t<decltype(std::declval<ParticleStore>().*field)>::value_type;
        if constexpr ((flags & kSnapshot) == 0 || (flags & kShift) != 0 || std::is_same_v<T, Quaternion>) {
          return;
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          x << "    <Attribute Name=\"" << info.snapshot << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
          item(info.snapshot, N.c_str(), "Int", 8);
          x << "    </Attribute>\n";
        } else {
          attribute(info.snapshot, doublesOf<T>() == 1 ? "Scalar" : "Vector", doublesOf<T>());
        }
      });
      attribute("force", "Vector", 3);
      attribute("axis", "Vector", 3);
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
