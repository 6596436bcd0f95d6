#pragma once
// Hot loops built twice, for AVX2/FMA machines (x86-64-v3) and for any
// x86-64, the one to run chosen at load time: block loops then vectorise
// with 256-bit registers and gathers where the CPU has them.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define FW_HOT_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define FW_HOT_CLONES
#endif
