#pragma once
// Small helpers over the HDF5 C API shared by the particle snapshots and the checkpoints: tables
// written in parallel by row blocks, whole tables read back, scalar/array attributes.
#include <hdf5.h>
#include <string>
#include <vector>

namespace vp::h5 {

// The file of one output step: <prefix>_<step, 6 digits>.h5 (fields, particles, checkpoint).
std::string stepFile(const char* prefix, int step);

// Turns HDF5's own error trace off while alive: callers report their own message.
class QuietErrors {
public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

private:
  H5E_auto2_t func_;
  void* data_;
};

// Writes this rank's rows [offset, offset + n) of a global total x cols dataset, collectively.
void writeRows(hid_t file, const char* name, hid_t type, const void* data, hsize_t total, hsize_t offset, hsize_t n,
               hsize_t cols);

// Reads a whole 1-D or 2-D dataset as doubles (independent read). Returns an error text, empty if
// it worked; rows/cols are its shape (cols = 1 for 1-D).
std::string readTable(hid_t file, const char* name, std::vector<double>& values, hsize_t& rows, hsize_t& cols);

// Attributes of a file or group: n doubles (or ints); a scalar when n = 1 unless asArray.
void writeAttribute(hid_t loc, const char* name, const double* v, int n, bool asArray = false);
void writeAttribute(hid_t loc, const char* name, const int* v, int n);
void writeAttribute(hid_t loc, const char* name, const std::string& text);
// False if the attribute is missing or has another length.
bool readAttribute(hid_t loc, const char* name, double* v, int n);
bool readAttribute(hid_t loc, const char* name, int* v, int n);
bool readAttribute(hid_t loc, const char* name, std::string& text);

} // namespace vp::h5
