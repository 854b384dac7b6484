#pragma once
// A CSV time series written by rank 0 (diagnostics.csv, particle_<id>.csv): a header row, then
// one row of numbers per call, flushed so a running case can be followed and plotted.
#include <cstdio>
#include <mpi.h>
#include <string>
#include <vector>

namespace vp {

// For a restart: keeps the header and the rows whose first column is <= last (relative 1e-9),
// dropping the rows a longer or crashed run wrote after the checkpoint (rewritten through a
// temporary file). False if there is no such file. Rank 0 only.
bool keepRowsUpTo(const std::string& path, double last);

class CsvWriter {
public:
  // resumeAfter (a restart): continue the file after the row with this first column, if it exists.
  CsvWriter(MPI_Comm comm, const std::string& path, const std::vector<std::string>& columns,
            double resumeAfter = -1);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void row(const std::vector<double>& values);  // collective-free: only rank 0 writes

private:
  std::string path_;
  std::FILE* file_ = nullptr;
  size_t columns_;
};

} // namespace vp
