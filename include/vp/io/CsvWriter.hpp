#pragma once
// A CSV time series written by rank 0 (diagnostics.csv, particle_<id>.csv): a header row, then
// one row of numbers per call, flushed so a running case can be followed and plotted.
#include <cstdio>
#include <mpi.h>
#include <string>
#include <vector>

namespace vp {

class CsvWriter {
public:
  CsvWriter(MPI_Comm comm, const std::string& path, const std::vector<std::string>& columns);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void row(const std::vector<double>& values);  // collective-free: only rank 0 writes

private:
  std::FILE* file_ = nullptr;
  size_t columns_;
};

} // namespace vp
