// The decomposition check's texts: --domains ("2,2,1") and --seeding ("grid:32"), read and written.
#include <algorithm>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/dpd/decomposition.hpp"
#include "dpdrng/rng/seeding_repair.hpp"

namespace dpdrng::dpd {

DomainGrid parse_domains(std::string_view text) {
  DomainGrid g;
  const std::string t(text);
  const std::string why = "--domains must be 1 to 3 comma-separated counts in 1..64 (\"2\", \"2,2,1\"), got '" + t + "'";
  std::size_t pos = 0;
  int axis = 0;
  while (true) {
    if (axis == 3) throw InputError(why);
    const std::size_t comma = t.find(',', pos);
    const std::string part = t.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (part.empty() || part.size() > 2 || !std::all_of(part.begin(), part.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
      throw InputError(why);
    const int v = std::stoi(part);
    if (v < 1 || v > 64) throw InputError(why);
    g.n[axis++] = v;
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return g;
}

std::string to_string(const DomainGrid& g) {
  return std::to_string(g.n[0]) + "x" + std::to_string(g.n[1]) + "x" + std::to_string(g.n[2]);
}

DecompSeeding parse_decomp_seeding(std::string_view text) {
  DecompSeeding s;
  if (text == "distance") return s;
  if (text == "pair-step") return s.kind = DecompSeedingKind::pair_step, s;
  if (text == "canonical") return s.kind = DecompSeedingKind::canonical, s;
  if (text == "grid") return s.kind = DecompSeedingKind::grid, s;
  if (text.starts_with("grid:")) {
    const std::string k(text.substr(5));
    const bool digits = !k.empty() && k.size() <= 2 && std::all_of(k.begin(), k.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int bits = digits ? std::stoi(k) : -1;
    if (bits < rng::kMinGridBits || bits > rng::kMaxGridBits)
      throw InputError("grid seeding: the grid exponent K in 'grid:K' must be " + std::to_string(rng::kMinGridBits) +
                       ".." + std::to_string(rng::kMaxGridBits) + ", got '" + k + "'");
    s.kind = DecompSeedingKind::grid;
    s.grid_bits = bits;
    return s;
  }
  throw InputError("unknown seeding '" + std::string(text) +
                   "' (known: distance, pair-step, grid, grid:K, canonical)");
}

std::string to_string(const DecompSeeding& s) {
  switch (s.kind) {
    case DecompSeedingKind::distance: return "distance";
    case DecompSeedingKind::pair_step: return "pair-step";
    case DecompSeedingKind::canonical: return "canonical";
    case DecompSeedingKind::grid: return "grid:" + std::to_string(s.grid_bits);
  }
  return "?";
}

}  // namespace dpdrng::dpd
