#pragma once
// Where a benchmark ran: the CPU's model name and the vector width this build was compiled for, so that a
// figure quoted from `bench` output carries its machine with it.
#include <istream>
#include <string>

namespace dpdrng {

// The first CPU's "model name" of /proc/cpuinfo, trimmed, followed by "(family F, model M)" where cpuinfo gives
// them (x86); "unknown" where there is no model name (no /proc, or an ARM kernel that lists no such field).
std::string cpu_model();
// The same from a cpuinfo-formatted text.
std::string cpu_model_from(std::istream& cpuinfo);

// Bits of the widest SIMD registers the compiler was allowed to use: 512 (AVX-512F), 256 (AVX2), 128 (SSE2 or
// NEON), 64 with none of them.
int simd_width_bits();
// Its instruction set: "avx512f", "avx2", "sse2", "neon" or "none".
const char* simd_name();

}  // namespace dpdrng
