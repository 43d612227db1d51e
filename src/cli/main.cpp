// dpdrng: thin glue from the command line to the library; every subcommand registers itself (registry.hpp).
#include <gsl/gsl_errno.h>

#include <algorithm>
#include <iostream>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"

namespace dpdrng::cli {
std::vector<std::pair<int, Attach>>& commands();
}

int main(int argc, char** argv) {
  // GSL's default handler aborts; every GSL call in the library checks its status instead.
  gsl_set_error_handler_off();
  CLI::App app{"dpdrng: how cheap may the per-pair random numbers of a DPD simulation be?\n"
               "Hash generators, statistical tests, a DPD engine and a study driver in one tool.",
               "dpdrng"};
  app.set_version_flag("--version", std::string("dpdrng ") + DPDRNG_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);
  auto& list = dpdrng::cli::commands();
  std::stable_sort(list.begin(), list.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (auto& [order, attach] : list) attach(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "dpdrng: " << e.what() << " (see --help)\n";
    return dpdrng::kExitBadInput;
  } catch (const dpdrng::InputError& e) {
    std::cerr << "dpdrng: " << e.what() << "\n";
    return dpdrng::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "dpdrng: internal error: " << e.what() << "\n";
    return dpdrng::kExitInternal;
  }
  return dpdrng::kExitOk;
}
