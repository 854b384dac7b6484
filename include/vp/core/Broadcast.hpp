#pragma once
// One rank's text to every rank (a decision or a message taken on one rank: an error, a record).
#include <mpi.h>
#include <string>

namespace vp {

inline void broadcast(MPI_Comm comm, std::string& text, int root = 0)
{
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm);
  text.resize(length);
  MPI_Bcast(text.data(), length, MPI_CHAR, root, comm);
}

} // namespace vp
