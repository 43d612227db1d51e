// The benchmarks' machine description: the cpuinfo parser on texts in the kernel's formats, and the SIMD width
// against the compiler's own macros.
#include <gtest/gtest.h>

#include <sstream>

#include "dpdrng/common/machine.hpp"

namespace dpdrng_test::common_test_machine {

using namespace dpdrng;

namespace {
std::string model_of(const std::string& text) {
  std::istringstream in(text);
  return cpu_model_from(in);
}
}  // namespace

TEST(Machine, CpuModelIsTheFirstCpusModelNameFamilyAndModel) {
  // x86 Linux: "model" precedes "model name", and every CPU repeats the block.
  EXPECT_EQ(model_of("processor\t: 0\nvendor_id\t: AuthenticAMD\ncpu family\t: 25\nmodel\t\t: 1\n"
                     "model name\t: AMD EPYC 7763 64-Core Processor  \nstepping\t: 1\n\nprocessor\t: 1\n"
                     "model name\t: second\n"),
            "AMD EPYC 7763 64-Core Processor (family 25, model 1)");
  EXPECT_EQ(model_of("model name\t: Intel(R) Xeon(R) Processor\r\n"), "Intel(R) Xeon(R) Processor");
  EXPECT_EQ(model_of("cpu family\t: 6\nmodel\t\t: 207\nmodel name\t: Intel(R) Xeon(R) Processor\n"),
            "Intel(R) Xeon(R) Processor (family 6, model 207)");
}

TEST(Machine, CpuModelFallsBackToUnknown) {
  // arm64 kernels list "CPU part" and no model name.
  EXPECT_EQ(model_of("processor\t: 0\nBogoMIPS\t: 50.00\nCPU implementer\t: 0x41\nCPU part\t: 0xd0c\n"), "unknown");
  EXPECT_EQ(model_of(""), "unknown");
  EXPECT_EQ(model_of("model name\t:   \n"), "unknown");
  EXPECT_EQ(model_of("model names\t: not this\n"), "unknown");
  EXPECT_FALSE(cpu_model().empty());
}

TEST(Machine, SimdWidthMatchesTheCompilersMacros) {
#if defined(__AVX512F__)
  EXPECT_EQ(simd_width_bits(), 512);
#elif defined(__AVX2__)
  EXPECT_EQ(simd_width_bits(), 256);
#elif defined(__SSE2__)
  EXPECT_EQ(simd_width_bits(), 128);
#endif
  EXPECT_EQ(std::string(simd_name()) == "avx512f", simd_width_bits() == 512);
}

}  // namespace dpdrng_test::common_test_machine
