#include "vp/io/FieldWriter.hpp"
#include "vp/core/Error.hpp"
#include "vp/fluid/Operators.hpp"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <petscviewerhdf5.h>

namespace vp {

namespace {

std::string fieldFile(int step)
{
  char name[64];
  std::snprintf(name, sizeof name, "fields_%06d.h5", step);
  return name;
}

void writeAttribute(hid_t loc, const char* name, const double* v, hsize_t n)
{
  hid_t space = H5Screate_simple(1, &n, nullptr);
  hid_t attr = H5Acreate2(loc, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, v);
  H5Aclose(attr);
  H5Sclose(space);
}

} // namespace

void makeOutputDir(MPI_Comm comm, const std::string& dir)
{
  int rank, ok = 1;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    ok = std::filesystem::is_directory(dir) ? 1 : 0;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
  if (!ok) throw InputError("option -output_dir: cannot create directory '" + dir + "'");
}

FieldWriter::FieldWriter(const Grid& grid, std::string dir) : grid_(grid), dir_(std::move(dir))
{
  VP_CALL(DMCreateGlobalVector(grid.cellVectorDM(), &centre_));
  VP_CALL(PetscObjectSetName((PetscObject)centre_, "velocity"));
}

FieldWriter::~FieldWriter() { VecDestroy(&centre_); }

void FieldWriter::write(int step, double time, Vec velocityLocal, Vec pressure)
{
  {
    PetscScalar ****u, ****c;
    VP_CALL(DMDAVecGetArrayDOFRead(grid_.faceDM(), velocityLocal, &u));
    VP_CALL(DMDAVecGetArrayDOF(grid_.cellVectorDM(), centre_, &c));
    ops::faceToCentre(grid_, u, c);
    VP_CALL(DMDAVecRestoreArrayDOF(grid_.cellVectorDM(), centre_, &c));
    VP_CALL(DMDAVecRestoreArrayDOFRead(grid_.faceDM(), velocityLocal, &u));
  }
  const std::string path = dir_ + "/" + fieldFile(step);
  PetscViewer viewer;
  VP_CALL(PetscViewerHDF5Open(grid_.comm(), path.c_str(), FILE_MODE_WRITE, &viewer));
  VP_CALL(VecView(centre_, viewer));
  VP_CALL(PetscObjectSetName((PetscObject)pressure, "pressure"));
  VP_CALL(VecView(pressure, viewer));
  VP_CALL(PetscViewerDestroy(&viewer));

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
    writeAttribute(root, "time", &time, 1);
    writeAttribute(root, "step", &stepValue, 1);
    writeAttribute(root, "origin", origin, 3);
    writeAttribute(root, "spacing", spacing, 3);
    H5Gclose(root);
    H5Fclose(file);
    snapshots_.emplace_back(step, time);
    writeXdmf();
  }
  MPI_Barrier(grid_.comm());
}

void FieldWriter::writeXdmf() const
{
  const int nx = grid_.n(0), ny = grid_.n(1), nz = grid_.n(2);
  const std::string tmp = dir_ + "/fields.xmf.tmp";
  {
    std::ofstream x(tmp);
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
      << "<Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& [step, time] : snapshots_) {
      const std::string file = fieldFile(step);
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
        << file << ":/pressure</DataItem>\n  </Attribute>\n"
        << "</Grid>\n";
    }
    x << "</Grid>\n</Domain>\n</Xdmf>\n";
  }
  std::filesystem::rename(tmp, dir_ + "/fields.xmf");
}

} // namespace vp
