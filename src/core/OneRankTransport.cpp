#include "vp/core/OneRankTransport.hpp"
#include <cstdlib>
#include <cstring>

namespace vp {

void useLocalTransportForOneRank()
{
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size && std::strcmp(size, "1") == 0) setenv("OMPI_MCA_pml", "ob1", 0);  // 0: a user's choice stays
}

} // namespace vp
