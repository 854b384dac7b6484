#include "vp/io/CsvWriter.hpp"
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace vp {

bool keepRowsUpTo(const std::string& path, double last)
{
  std::ifstream in(path);
  if (!in) return false;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    std::string line;
    if (std::getline(in, line)) out << line << '\n';  // header
    const double limit = last + 1e-9 * std::fabs(last);
    while (std::getline(in, line)) {
      char* end = nullptr;
      const double key = std::strtod(line.c_str(), &end);
      if (end == line.c_str() || key > limit) break;
      out << line << '\n';
    }
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot replace " + path);
  return true;
}

CsvWriter::CsvWriter(MPI_Comm comm, const std::string& path, const std::vector<std::string>& columns, double resumeAfter)
  : path_(path), columns_(columns.size())
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0) return;
  if (resumeAfter >= 0 && keepRowsUpTo(path, resumeAfter)) {
    file_ = std::fopen(path.c_str(), "a");
    if (!file_) throw std::runtime_error("cannot append to " + path);
    return;
  }
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
  if (std::fflush(file_) != 0 || std::ferror(file_))
    throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

} // namespace vp
