#include "vp/io/Hdf5.hpp"
#include <cstdio>
#include <stdexcept>

namespace vp::h5 {

std::string stepFile(const char* prefix, int step)
{
  char name[96];
  std::snprintf(name, sizeof name, "%s_%06d.h5", prefix, step);
  return name;
}

QuietErrors::QuietErrors()
{
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

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
  // An empty table (no contacts yet) is just created: MPI-IO rejects a zero-size collective write.
  const herr_t err = total > 0 ? H5Dwrite(ds, type, mspace, fspace, xfer, data) : 0;
  H5Pclose(xfer);
  H5Sclose(mspace);
  H5Dclose(ds);
  H5Sclose(fspace);
  if (err < 0) throw std::runtime_error(std::string("HDF5: cannot write dataset ") + name);
}

std::string readTable(hid_t file, const char* name, std::vector<double>& values, hsize_t& rows, hsize_t& cols)
{
  QuietErrors quiet;
  hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
  if (ds < 0) return std::string("lacks the dataset ") + name;
  hid_t sp = H5Dget_space(ds);
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_ndims(sp);
  std::string error;
  if (rank < 1 || rank > 2)
    error = std::string("dataset ") + name + " must be 1-D or 2-D";
  else {
    H5Sget_simple_extent_dims(sp, dims, nullptr);
    rows = dims[0];
    cols = rank == 2 ? dims[1] : 1;
    values.resize(rows * cols);
    if (!values.empty() && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      error = std::string("dataset ") + name + " cannot be read as numbers";
  }
  H5Sclose(sp);
  H5Dclose(ds);
  return error;
}

namespace {

void writeAttr(hid_t loc, const char* name, hid_t type, const void* v, int n, bool asArray = false)
{
  const hsize_t dims = n;
  hid_t space = n == 1 && !asArray ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &dims, nullptr);
  hid_t attr = H5Acreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t err = attr < 0 ? -1 : H5Awrite(attr, type, v);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  if (err < 0) throw std::runtime_error(std::string("HDF5: cannot write attribute ") + name);
}

bool readAttr(hid_t loc, const char* name, hid_t type, void* v, int n)
{
  QuietErrors quiet;
  if (H5Aexists(loc, name) <= 0) return false;
  hid_t attr = H5Aopen(loc, name, H5P_DEFAULT);
  hid_t space = H5Aget_space(attr);
  const bool ok = H5Sget_simple_extent_npoints(space) == n && H5Aread(attr, type, v) >= 0;
  H5Sclose(space);
  H5Aclose(attr);
  return ok;
}

} // namespace

void writeAttribute(hid_t loc, const char* name, const double* v, int n, bool asArray)
{
  writeAttr(loc, name, H5T_NATIVE_DOUBLE, v, n, asArray);
}
void writeAttribute(hid_t loc, const char* name, const int* v, int n) { writeAttr(loc, name, H5T_NATIVE_INT, v, n); }

void writeAttribute(hid_t loc, const char* name, const std::string& text)
{
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, text.size() + 1);
  writeAttr(loc, name, type, text.c_str(), 1);
  H5Tclose(type);
}

bool readAttribute(hid_t loc, const char* name, double* v, int n) { return readAttr(loc, name, H5T_NATIVE_DOUBLE, v, n); }
bool readAttribute(hid_t loc, const char* name, int* v, int n) { return readAttr(loc, name, H5T_NATIVE_INT, v, n); }

bool readAttribute(hid_t loc, const char* name, std::string& text)
{
  QuietErrors quiet;
  if (H5Aexists(loc, name) <= 0) return false;
  hid_t attr = H5Aopen(loc, name, H5P_DEFAULT);
  hid_t type = H5Aget_type(attr);
  bool ok = H5Tget_class(type) == H5T_STRING;
  if (ok) {
    std::string buf(H5Tget_size(type), '\0');
    ok = H5Aread(attr, type, buf.data()) >= 0;
    text = buf.c_str();
  }
  H5Tclose(type);
  H5Aclose(attr);
  return ok;
}

} // namespace vp::h5
