// SIMCAP_AVX2_CLONES: marks a hot per-lane loop function to be compiled twice, for AVX2 and for
// the baseline, the loader picking the clone the CPU runs (GCC/Clang function multiversioning).
#pragma once

// AVX2 without FMA: the clones round every operation as the baseline does (no contracted
// multiply-adds), so images stay byte-identical on every CPU; the lane loops run 8 floats wide.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__AVX2__)
#define SIMCAP_AVX2_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define SIMCAP_AVX2_CLONES
#endif
