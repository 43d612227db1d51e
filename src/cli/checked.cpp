#include "dpdrng/cli/checked.hpp"

#include <cstdio>
#include <stdexcept>

namespace dpdrng::cli {

CLI::Validator checked_integer(const IntRange& range, bool is_signed) {
  return CLI::Validator(
             [range, is_signed](std::string& text) -> std::string {
               std::string problem;
               if (is_signed) {
                 std::int64_t v = 0;
                 problem = check_integer(text, range, v);
                 if (problem.empty()) text = std::to_string(v);
               } else {
                 std::uint64_t v = 0;
                 problem = check_unsigned(text, range, v);
                 if (problem.empty()) text = std::to_string(v);
               }
               return problem;
             },
             "")
      .name(kCheckedNumber);
}

CLI::Validator checked_real(const RealRange& range) {
  return CLI::Validator(
             [range](std::string& text) -> std::string {
               double v = 0;
               std::string problem = check_real(text, range, v);
               if (problem.empty()) {
                 char buf[40];
                 std::snprintf(buf, sizeof buf, "%.17g", v);
                 text = buf;
               }
               return problem;
             },
             "")
      .name(kCheckedNumber);
}

CLI::Option* add_real(CLI::App& app, const std::string& name, double& value, const std::string& help,
                      const RealRange& range) {
  return app.add_option(name, value, help)->transform(checked_real(range))->capture_default_str();
}

CLI::Option* add_threads(CLI::App& app, int& threads, const std::string& help) {
  return add_integer(app, "--threads", threads, help, {0, 1024});
}

const CLI::Validator& non_empty_path() {
  static const CLI::Validator v([](std::string& text) -> std::string { return text.empty() ? "an empty path names nothing" : ""; },
                                "");
  return v;
}

void require_checked_numbers(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size() == 0) continue;  // a flag
    const std::string type = opt->get_type_name();
    const bool numeric = type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0 || type.rfind("FLOAT", 0) == 0;
    if (!numeric) continue;
    try {
      opt->get_validator(kCheckedNumber);
    } catch (const CLI::OptionNotFound&) {
      throw std::logic_error("option " + opt->get_name() + " of '" + app.get_name() +
                             "' bypasses the checked-number parser (use add_integer/add_real)");
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) require_checked_numbers(*sub);
}

}  // namespace dpdrng::cli
