#include "dpdrng/rng/defect.hpp"

#include <cmath>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"

namespace dpdrng::rng {

bool is_defect(std::string_view name) { return name == "defect" || name.starts_with(kDefectPrefix); }

std::string defect_syntax() {
  return "defect:variance=E,lag1=R,mean=M,aniso=K,key=N,base=philox4x32 (each optional; E > -1, |R| <= 1/2, M "
         "finite, -1/2 < K < 1, N an integer in [0, 2^32) replacing the base key's second word; aniso needs distance "
         "seeding)";
}

namespace {
// The weight a of η_{t−1} that gives corr(ζ_t, ζ_{t−1}) = a·√(1−a²) = ρ: a² = (1 − √(1 − 4ρ²))/2, the root
// with |a| ≤ 1/√2 (the other root swaps the roles of η_{t−1} and η_t), sign of ρ.
double lag1_weight(double rho) {
  const double a = std::sqrt((1.0 - std::sqrt(1.0 - 4.0 * rho * rho)) / 2.0);
  return rho < 0 ? -a : a;
}

[[noreturn]] void fail(std::string_view name, const std::string& why) {
  throw InputError("generator " + quote_input(name) + ": " + why + "; expected " + defect_syntax());
}
}  // namespace

DefectParams parse_defect(std::string_view name) {
  if (!is_defect(name)) fail(name, "not a defect generator");
  DefectParams p;
  if (name == "defect") return p;
  std::string_view rest = name.substr(kDefectPrefix.size());
  if (rest.empty()) fail(name, "no parameters after 'defect:'");
  bool seen[6] = {false, false, false, false, false, false};
  for (;;) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) fail(name, "'" + std::string(item) + "' is not key=value");
    const std::string_view key = item.substr(0, eq), value = item.substr(eq + 1);
    const std::string what = "generator " + quote_input(name) + ": " + std::string(key);
    int k = -1;
    if (key == "variance") {
      k = 0, p.variance = parse_real(value, what, {-1.0, 1e6, true, false});
    } else if (key == "lag1") {
      k = 1, p.lag1 = lag1_weight(parse_real(value, what, {-0.5, 0.5, false, false}));
    } else if (key == "mean") {
      k = 2, p.mean = parse_real(value, what, {-1e6, 1e6, false, false});
    } else if (key == "aniso") {
      k = 4, p.aniso = parse_real(value, what, {-0.5, 1.0, true, true});
    } else if (key == "key") {
      k = 5, p.key = parse_number<std::uint32_t>(value, what);
    } else if (key == "base") {
      k = 3;
      if (value != "philox4x32" && value != "philox4x32(10)")
        fail(name, "base '" + std::string(value) + "' is not available (philox4x32 only)");
    } else {
      fail(name, "unknown key '" + std::string(key) + "'");
    }
    if (seen[k]) fail(name, "'" + std::string(key) + "' given twice");
    seen[k] = true;
    if (comma == std::string_view::npos) return p;
    rest.remove_prefix(comma + 1);
  }
}

}  // namespace dpdrng::rng
