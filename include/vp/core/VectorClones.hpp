#pragma once
// VP_VECTOR_CLONES before a function with hot, vectorisable loops compiles it three times, for the
// x86-64 levels v4 (AVX-512), v3 (AVX2 + FMA) and the baseline (SSE2), and the loader picks the best
// one the CPU has: the binary stays portable and still uses wide vectors where they exist (the
// viscous sweep is 1.3x and the advection sweep, whose selects SSE2 lacks, 2.3x faster with
// AVX-512 than with SSE2, benchmarks/RESULTS.md). The clones may round differently (fused
// multiply-adds, wider partial sums), so results agree across CPU types to round-off, not to the
// bit; on one machine every rank runs the same clone. Other compilers and architectures get the
// plain function.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define VP_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define VP_VECTOR_CLONES
#endif
