// Writes the libFuzzer dictionary of fuzz_argv from the registry: every subcommand path and every option name
// (long and short), each also behind a NUL so that one insertion starts a new argument.
// Usage: make_argv_dict > fuzz/argv.dict
#include <iostream>
#include <set>
#include <string>

#include "argv_tree.hpp"
#include "dpdrng/cli/run.hpp"

namespace {

void option_names(CLI::App& app, std::set<std::string>& out) {
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) out.insert("--" + n);
    for (const std::string& n : o->get_snames()) out.insert("-" + n);
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) option_names(*sub, out);
}

}  // namespace

int main() {
  auto app = dpdrng::cli::make_app();
  std::vector<std::string> paths;
  dpdrng::fuzz::subcommand_paths(*app, "", paths);
  std::set<std::string> words(paths.begin(), paths.end());
  option_names(*app, words);
  std::cout << "# libFuzzer dictionary of fuzz_argv, written by make_argv_dict: subcommand paths and option names.\n";
  for (const std::string& w : words) std::cout << '"' << w << "\"\n\"\\x00" << w << "\"\n";
  return 0;
}
