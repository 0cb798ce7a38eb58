#pragma once
// Which target-specific SIMD code this build holds (docs/PORTABILITY.md).
// VRI_SIMD is the CMake option (ON by default, the compile definition 1);
// OFF, or a target other than x86-64, leaves the portable code alone: the
// scalar ray marches and the tables' GCC generic vectors compiled for the
// target's baseline. The ray marches give the same bytes on every path; the
// x86-64-v3 table clones may round differently (GCC contracts a * b + c into
// FMA there), and other targets build with -ffp-contract=off (top-level
// CMakeLists.txt, docs/PORTABILITY.md).

#ifndef VRI_SIMD
#define VRI_SIMD 1
#endif

#if VRI_SIMD && defined(__x86_64__)
// The 8-lane AVX2 ray packets (methods/preint/float_packet.cpp), used where the
// CPU has AVX2 (checked at run time).
#define VRI_HAVE_AVX2_PACKETS 1
// The table kernels compiled twice, AVX2 + FMA and the x86-64 baseline, one
// picked at load time (ifunc). Only x86 knows these arch names.
#define VRI_TARGET_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
// Compiled twice, AVX2 without FMA and the baseline: code that must give the
// same bytes in both (core/f64x4.hpp's vectors; neither fuses a * b + c).
#define VRI_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define VRI_HAVE_AVX2_PACKETS 0
#define VRI_TARGET_CLONES
#define VRI_AVX2_CLONES
#endif
