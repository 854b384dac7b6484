#include "vp/io/FieldWriter.hpp"
#include "vp/core/Error.hpp"
#include "vp/fluid/Operators.hpp"
#include "vp/io/Hdf5.hpp"
#include "vp/io/RunRecord.hpp"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <petscviewerhdf5.h>

namespace vp {

FieldWriter::FieldWriter(const Grid& grid, std::string dir) : grid_(grid), dir_(std::move(dir))
{
  VP_CALL(DMCreateGlobalVector(grid.cellVectorDM(), &centre_));
  VP_CALL(PetscObjectSetName((PetscObject)centre_, "velocity"));
}

FieldWriter::~FieldWriter()
{
  VecDestroy(&chiLocal_);
  VecDestroy(&chiCell_);
  VecDestroy(&centre_);
}

void FieldWriter::write(int step, double time, Vec velocityLocal, Vec pressure, Vec chi)
{
  if (chi) {
    if (!chiCell_) {
      VP_CALL(DMCreateGlobalVector(grid_.cellDM(), &chiCell_));
      VP_CALL(PetscObjectSetName((PetscObject)chiCell_, "chi"));
      VP_CALL(DMCreateLocalVector(grid_.faceDM(), &chiLocal_));
    }
    // Periodic ghosts come from PETSc; beyond a wall the mask is zero (local vectors start at 0).
    VP_CALL(VecSet(chiLocal_, 0));
    VP_CALL(DMGlobalToLocal(grid_.faceDM(), chi, INSERT_VALUES, chiLocal_));
    PetscScalar ****f, ***c;
    VP_CALL(DMDAVecGetArrayDOFRead(grid_.faceDM(), chiLocal_, &f));
    VP_CALL(DMDAVecGetArray(grid_.cellDM(), chiCell_, &c));
    for (PetscInt k = grid_.start(2); k < grid_.end(2); ++k)
      for (PetscInt j = grid_.start(1); j < grid_.end(1); ++j)
        for (PetscInt i = grid_.start(0); i < grid_.end(0); ++i)
          c[k][j][i] = (f[k][j][i][0] + f[k][j][i + 1][0] + f[k][j][i][1] + f[k][j + 1][i][1] + f[k][j][i][2] +
                        f[k + 1][j][i][2]) / 6;
    VP_CALL(DMDAVecRestoreArray(grid_.cellDM(), chiCell_, &c));
    VP_CALL(DMDAVecRestoreArrayDOFRead(grid_.faceDM(), chiLocal_, &f));
  }
  {
    PetscScalar ****u, ****c;
    VP_CALL(DMDAVecGetArrayDOFRead(grid_.faceDM(), velocityLocal, &u));
    VP_CALL(DMDAVecGetArrayDOF(grid_.cellVectorDM(), centre_, &c));
    ops::faceToCentre(grid_, u, c);
    VP_CALL(DMDAVecRestoreArrayDOF(grid_.cellVectorDM(), centre_, &c));
    VP_CALL(DMDAVecRestoreArrayDOFRead(grid_.faceDM(), velocityLocal, &u));
  }
  const std::string path = dir_ + "/" + h5::stepFile("fields", step);
  VP_CALL(PetscObjectSetName((PetscObject)pressure, "pressure"));
  {
    QuietPetscErrors quiet;
    PetscViewer viewer = nullptr;
    PetscErrorCode e = PetscViewerHDF5Open(grid_.comm(), path.c_str(), FILE_MODE_WRITE, &viewer);
    if (!e) e = VecView(centre_, viewer);
    if (!e) e = VecView(pressure, viewer);
    if (!e && chi) e = VecView(chiCell_, viewer);
    PetscViewerDestroy(&viewer);
    if (e) throw std::runtime_error("cannot write " + path + " (HDF5 error " + std::to_string(e) + "; disk full?)");
  }

  int rank;
  MPI_Comm_rank(grid_.comm(), &rank);
  if (rank == 0) {
    // Geometry and time as root attributes, written serially once the parallel file is closed.
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (file < 0) throw std::runtime_error("cannot reopen " + path);
    hid_t root = H5Gopen2(file, "/", H5P_DEFAULT);
    const double origin[3] = {grid_.lo(0), grid_.lo(1), grid_.lo(2)};
    const double spacing[3] = {grid_.h(0), grid_.h(1), grid_.h(2)};
    const double stepValue = step;
    h5::writeAttribute(root, "time", &time, 1, true);
    h5::writeAttribute(root, "step", &stepValue, 1, true);
    h5::writeAttribute(root, "origin", origin, 3, true);
    h5::writeAttribute(root, "spacing", spacing, 3, true);
    h5::writeAttribute(root, "vpsolve_run", runRecord());
    H5Gclose(root);
    H5Fclose(file);
    snapshots_.emplace_back(step, time);
    writeXdmf(chi != nullptr);
  }
  MPI_Barrier(grid_.comm());
}

std::vector<double> FieldWriter::snapshotList() const
{
  std::vector<double> out;
  for (const auto& [step, time] : snapshots_) out.insert(out.end(), {double(step), time});
  return out;
}

void FieldWriter::resume(const std::vector<double>& list)
{
  snapshots_.clear();
  for (std::size_t k = 0; k + 1 < list.size(); k += 2) {
    const int step = static_cast<int>(list[k]);
    if (std::filesystem::exists(dir_ + "/" + h5::stepFile("fields", step))) snapshots_.emplace_back(step, list[k + 1]);
  }
}

void FieldWriter::writeXdmf(bool chi) const
{
  const int nx = grid_.n(0), ny = grid_.n(1), nz = grid_.n(2);
  const std::string tmp = dir_ + "/fields.xmf.tmp";
  {
    std::ofstream x(tmp);
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
      << "<Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& [step, time] : snapshots_) {
      const std::string file = h5::stepFile("fields", step);
      x << "<Grid Name=\"step " << step << "\" GridType=\"Uniform\">\n"
        << "  <Time Value=\"" << time << "\"/>\n"
        << "  <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nz + 1 << " " << ny + 1 << " " << nx + 1 << "\"/>\n"
        << "  <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
        << "    <DataItem Dimensions=\"3\" Format=\"XML\">" << grid_.lo(2) << " " << grid_.lo(1) << " " << grid_.lo(0) << "</DataItem>\n"
        << "    <DataItem Dimensions=\"3\" Format=\"XML\">" << grid_.h(2) << " " << grid_.h(1) << " " << grid_.h(0) << "</DataItem>\n"
        << "  </Geometry>\n"
        << "  <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n"
        << "    <DataItem Dimensions=\"" << nz << " " << ny << " " << nx << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
        << file << ":/velocity</DataItem>\n  </Attribute>\n"
        << "  <Attribute Name=\"pressure\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "    <DataItem Dimensions=\"" << nz << " " << ny << " " << nx << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
        << file << ":/pressure</DataItem>\n  </Attribute>\n";
      if (chi)
        x << "  <Attribute Name=\"chi\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
          << "    <DataItem Dimensions=\"" << nz << " " << ny << " " << nx << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
          << file << ":/chi</DataItem>\n  </Attribute>\n";
      x << "</Grid>\n";
    }
    x << "</Grid>\n</Domain>\n</Xdmf>\n";
    x.close();
    // A failed write (a full disk) keeps the previous index.
    if (!x) {
      std::filesystem::remove(tmp);
      throw std::runtime_error("cannot write " + tmp + " (disk full?); fields.xmf is kept as it was");
    }
  }
  std::filesystem::rename(tmp, dir_ + "/fields.xmf");
}

} // namespace vp
