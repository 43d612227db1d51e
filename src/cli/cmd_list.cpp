// dpdrng list: the generators, their round ranges and the round counts their authors call safe.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/rng/defect.hpp"
#include "dpdrng/rng/registry.hpp"

namespace dpdrng::cli {
namespace cmd_list {
namespace {

std::string rounds_text(const rng::GeneratorInfo& g) {
  if (g.min_rounds == g.max_rounds) return "-";
  return std::to_string(g.min_rounds) + ".." + std::to_string(g.max_rounds) + " (default " +
         std::to_string(g.default_rounds) + ")";
}

void run_list(bool json) {
  begin_work();
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& g : rng::generator_table()) {
      out.push_back({{"name", g.name},
                     {"default_rounds", g.default_rounds},
                     {"min_rounds", g.min_rounds},
                     {"max_rounds", g.max_rounds},
                     {"safe_rounds", g.safe_rounds},
                     {"description", g.description},
                     {"keyed_hash", g.keyed_hash}});
      out.back()["syntax"] = g.name == "defect" ? rng::defect_syntax() : std::string(g.name);
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (const auto& g : rng::generator_table()) {
    std::printf("%-13s rounds %-18s %s\n", std::string(g.name).c_str(), rounds_text(g).c_str(),
                g.keyed_hash ? "keyed hash (pair seedings, counter streams)" : "sequential stream only");
    std::printf("%13s %s\n%13s safe: %s\n", "", std::string(g.description).c_str(), "",
                std::string(g.safe_rounds).c_str());
    if (g.name == "defect")
      std::printf("%13s name: %s\n%13s zeta = mean + sqrt(1+variance) * (w * eta(t-1) + sqrt(1-w^2) * eta(t)), w sqrt(1-w^2) = lag1,\n"
                  "%13s eta = Philox4x32-10's zeta; corr(zeta(t), zeta(t-1)) = lag1; lag1 needs seeding pair-step\n",
                  "", rng::defect_syntax().c_str(), "", "");
  }
  std::printf("%-13s your own keyed hash in a shared library (C header dpdrng/plugin.h; docs/plugins.md)\n",
              "ext:PATH");
}

const bool registered = register_command(5, [](CLI::App& root) {
  auto json = std::make_shared<bool>(false);
  CLI::App* sub = root.add_subcommand("list", "the generators, their round ranges and the round counts called safe");
  sub->alias("generators");
  sub->add_flag("--json", *json, "machine-readable output");
  sub->callback([json] { run_list(*json); });
});

}  // namespace
}  // namespace cmd_list
}  // namespace dpdrng::cli
