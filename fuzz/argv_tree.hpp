#pragma once
// The subcommand paths of the CLI, walked from the app the registry builds: the argument harness picks one per
// input, and make_argv_dict lists them with every option name.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace dpdrng::fuzz {

// Every subcommand as the words that reach it ("gen", "nist", "nist runs", "study run", ...), parents first.
inline void subcommand_paths(CLI::App& app, const std::string& prefix, std::vector<std::string>& out) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    const std::string path = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    out.push_back(path);
    subcommand_paths(*sub, path, out);
  }
}

}  // namespace dpdrng::fuzz
