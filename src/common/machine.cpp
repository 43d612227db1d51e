#include "dpdrng/common/machine.hpp"

#include <fstream>

namespace dpdrng {

namespace {
// The value of "key\t: value" lines (keys padded with tabs or spaces), trimmed; empty for other keys.
std::string value_of(const std::string& line, const std::string& key) {
  const auto colon = line.find(':');
  if (colon == std::string::npos || line.compare(0, key.size(), key) != 0) return {};
  if (line.find_first_not_of(" \t", key.size()) != colon) return {};  // a longer key
  const auto b = line.find_first_not_of(" \t", colon + 1);
  if (b == std::string::npos) return {};
  return line.substr(b, line.find_last_not_of(" \t\r") + 1 - b);
}
}  // namespace

std::string cpu_model_from(std::istream& cpuinfo) {
  std::string name, family, model;
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos && !name.empty()) break;  // end of the first CPU
    if (name.empty()) name = value_of(line, "model name");
    if (family.empty()) family = value_of(line, "cpu family");
    if (model.empty()) model = value_of(line, "model");
  }
  if (name.empty()) return "unknown";
  // Virtual machines often show a generic name ("Intel(R) Xeon(R) Processor"): family and model tell them apart.
  if (!family.empty() && !model.empty()) name += " (family " + family + ", model " + model + ")";
  return name;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  return cpu_model_from(in);
}

int simd_width_bits() {
#if defined(__AVX512F__)
  return 512;
#elif defined(__AVX2__)
  return 256;
#elif defined(__SSE2__) || defined(__ARM_NEON)
  return 128;
#else
  return 64;
#endif
}

const char* simd_name() {
#if defined(__AVX512F__)
  return "avx512f";
#elif defined(__AVX2__)
  return "avx2";
#elif defined(__SSE2__)
  return "sse2";
#elif defined(__ARM_NEON)
  return "neon";
#else
  return "none";
#endif
}

}  // namespace dpdrng
