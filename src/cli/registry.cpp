#include "dpdrng/cli/registry.hpp"

#include <algorithm>
#include <sstream>
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

CLI::App& group(CLI::App& root, const std::string& name, const std::string& description) {
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return *sub;
  CLI::App* sub = root.add_subcommand(name, description);
  sub->require_subcommand(1);
  return *sub;
}

std::vector<long long> parse_int_list(const std::string& text, const std::string& what) {
  std::vector<long long> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(item, &used, 0);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size()) throw InputError(what + ": '" + item + "' is not an integer");
    out.push_back(v);
  }
  if (out.empty()) throw InputError(what + ": empty list");
  return out;
}

}  // namespace dpdrng::cli
