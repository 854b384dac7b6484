#pragma once
// PETSc's allocations of 2 MiB and more (field vectors, FFT buffers, matrices) on transparent huge
// pages. A fresh vector costs one page fault per 4 KiB page on first touch, and in a virtual machine
// a fault is dear: setting up the 64^3 cavity spent about half its 1.1 s there
// (benchmarks/RESULTS.md). Large blocks are aligned to 2 MiB and advised MADV_HUGEPAGE, then
// offset by a rotating multiple of 4 KiB + 64 B so that vectors do not all start in the same cache
// set (aligned starts made the stencil sweeps slower). Only advice: where the kernel declines,
// normal pages are used. Costs up to 2 MiB of memory per large block. VP_HUGE_PAGES=0 in the
// environment turns it off.

namespace vp {

// Installs the allocator. Call once, before PetscInitialize.
void allocateLargeOnHugePages();

} // namespace vp
