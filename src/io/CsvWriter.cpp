#include "vp/io/CsvWriter.hpp"
#include <stdexcept>

namespace vp {

CsvWriter::CsvWriter(MPI_Comm comm, const std::string& path, const std::vector<std::string>& columns)
  : columns_(columns.size())
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write " + path);
  for (size_t i = 0; i < columns.size(); ++i) std::fprintf(file_, "%s%s", i ? "," : "", columns[i].c_str());
  std::fprintf(file_, "\n");
}

CsvWriter::~CsvWriter()
{
  if (file_) std::fclose(file_);
}

void CsvWriter::row(const std::vector<double>& values)
{
  if (!file_) return;
  if (values.size() != columns_) throw std::logic_error("CsvWriter: row width differs from the header");
  for (size_t i = 0; i < values.size(); ++i) std::fprintf(file_, "%s%.10g", i ? "," : "", values[i]);
  std::fprintf(file_, "\n");
  std::fflush(file_);
}

} // namespace vp
