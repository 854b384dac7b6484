#include "vp/core/HugePages.hpp"
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <petscsys.h>
#include <string>
#include <sys/mman.h>

namespace vp {

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHeader = 64;  // room for Block before the returned address, keeps 64 B alignment

// Stored just before every block handed to PETSc: what free and realloc need.
struct Block {
  void* base;
  std::size_t size;
};

std::size_t nextColour = 0;

PetscErrorCode allocate(std::size_t n, PetscBool clear, int, const char[], const char[], void** out)
{
  *out = nullptr;
  if (n == 0) return 0;
  void* base = nullptr;
  std::size_t offset = kHeader;
  if (n >= kHugePage) {
    offset += (nextColour++ % 16) * (4096 + 64);
    if (posix_memalign(&base, kHugePage, n + offset) != 0) return PETSC_ERR_MEM;
    madvise(base, n + offset, MADV_HUGEPAGE);
  } else if (posix_memalign(&base, kHeader, n + offset) != 0) {
    return PETSC_ERR_MEM;
  }
  char* p = static_cast<char*>(base) + offset;
  const Block b{base, n};
  std::memcpy(p - sizeof(Block), &b, sizeof(Block));
  if (clear) std::memset(p, 0, n);
  *out = p;
  return 0;
}

Block blockOf(void* p)
{
  Block b;
  std::memcpy(&b, static_cast<char*>(p) - sizeof(Block), sizeof(Block));
  return b;
}

PetscErrorCode release(void* p, int, const char[], const char[])
{
  if (p) std::free(blockOf(p).base);
  return 0;
}

PetscErrorCode reallocate(std::size_t n, int line, const char fn[], const char file[], void** p)
{
  void* q = nullptr;
  if (n) {
    const PetscErrorCode e = allocate(n, PETSC_FALSE, line, fn, file, &q);
    if (e) return e;
    if (*p) std::memcpy(q, *p, std::min(blockOf(*p).size, n));
  }
  release(*p, line, fn, file);
  *p = q;
  return 0;
}

} // namespace

void allocateLargeOnHugePages()
{
  const char* env = std::getenv("VP_HUGE_PAGES");
  if (env && std::string(env) == "0") return;
  PetscMallocSet(allocate, release, reallocate);
}

} // namespace vp
