#pragma once
// Checked option values. Every numeric command-line option goes through the parser of dpdrng/common/numbers.hpp
// (decimal only, nothing clamped or wrapped, NaN and ±inf refused, the range in words), as a CLI11 transform that
// hands CLI11 the value in a form its own conversion reads exactly; paths may be required to be non-empty.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "dpdrng/common/numbers.hpp"

namespace dpdrng::cli {

inline constexpr std::uint64_t kIntMax = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
inline constexpr std::uint64_t kInt64Max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

// The transforms carry this name; require_checked_numbers() (run by make_app before parsing) refuses to start when
// a numeric option lacks one, so no option can slip past the parser.
inline constexpr const char* kCheckedNumber = "checked-number";
CLI::Validator checked_integer(const IntRange& range, bool is_signed);
CLI::Validator checked_real(const RealRange& range);
void require_checked_numbers(CLI::App& app);  // throws std::logic_error naming the option

// An integer option within `range` (default: the type's own), its default shown in --help.
template <class T>
CLI::Option* add_integer(CLI::App& app, const std::string& name, T& value, const std::string& help,
                         IntRange range = range_of<T>()) {
  const IntRange type = range_of<T>();
  if (range.lo < type.lo) range.lo = type.lo;
  if (range.hi > type.hi) range.hi = type.hi;
  return app.add_option(name, value, help)
      ->transform(checked_integer(range, std::is_signed_v<T>))
      ->capture_default_str();
}
// --threads: 0 (the default count) to 1024.
CLI::Option* add_threads(CLI::App& app, int& threads, const std::string& help);
// A real-valued option within `range` (default: any finite number), its default shown in --help.
CLI::Option* add_real(CLI::App& app, const std::string& name, double& value, const std::string& help,
                      const RealRange& range = {});

// Refuses "" for a path option (`--out ""` would otherwise mean "the default" or "nothing").
const CLI::Validator& non_empty_path();

}  // namespace dpdrng::cli
