#include "dpdrng/cli/registry.hpp"

#include <algorithm>
#include <vector>

#include "dpdrng/common/error.hpp"

namespace dpdrng::cli {

std::vector<std::pair<int, Attach>>& commands() {
  static std::vector<std::pair<int, Attach>> list;
  return list;
}

bool register_command(int order, Attach attach) {
  commands().emplace_back(order, std::move(attach));
  return true;
}

namespace {
bool validating = false;
}  // namespace

void set_validate_only(bool on) { validating = on; }
bool validate_only() { return validating; }

void begin_work() {
  if (validating) throw ArgumentsValid{};
}

CLI::App& group(CLI::App& root, const std::string& name, const std::string& description) {
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return *sub;
  CLI::App* sub = root.add_subcommand(name, description);
  sub->require_subcommand(1);
  return *sub;
}

}  // namespace dpdrng::cli
