// dpdrng: thin glue from the command line to the library; every subcommand registers itself (registry.hpp).
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/study/library_init.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::cli {
std::vector<std::pair<int, Attach>>& commands();

namespace {

// ~0.1 ms of spinning where a pause takes 40 ns (Intel Xeon family 6 model 167): longer than most waits at a barrier of
// the cells loop, where a thread that went to sleep costs the step a wake-up, and short against a scheduler's
// slice, which a thread spinning beside another process's busy loop would burn. Systems small enough for
// each wait to matter more than that run on one thread anyway (dpd::team_threads).
constexpr const char* kGompSpinCount = "3000";

// Help and version text go to standard output like any result: a lost one is a write error.
int exit_with_text(CLI::App& app, const CLI::ParseError& e) {
  const int code = app.exit(e);
  try {
    flush_standard_output();
  } catch (const OutputError& err) {
    std::cerr << "dpdrng: write error: " << err.what() << "\n";
    return kExitInternal;
  }
  return code;
}

// The deepest subcommand the parser entered (the root if none).
CLI::App* deepest(CLI::App* app) {
  for (CLI::App* sub : app->get_subcommands()) return deepest(sub);
  return app;
}

// CLI11 reports an unknown subcommand as "A subcommand is required"; say which word was not understood and
// which were expected.
std::string subcommand_message(CLI::App& root) {
  CLI::App* at = deepest(&root);
  std::string names;
  for (const CLI::App* sub : at->get_subcommands([](CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  const std::string path = at == &root ? "dpdrng" : "dpdrng " + at->get_name();
  const std::vector<std::string> extra = at->remaining();
  if (!extra.empty()) return "unknown command '" + extra.front() + "' for " + path + " (known: " + names + ")";
  return path + " needs a command (one of: " + names + ")";
}

// libgomp reads its wait policy once, when it is loaded, before main(): unless OMP_WAIT_POLICY or GOMP_SPINCOUNT
// says otherwise, a thread waiting at a barrier spins 300 000 pause instructions before it sleeps, ~12 ms where
// a pause takes 40 ns. On a machine shared with other work the spinning thread holds a core that a
// preempted team-mate needs, and a two-thread run ends up slower than one thread. Unless the user chose a
// policy, the process therefore runs itself again, once, with a short spin (kGompSpinCount).
void bound_openmp_spin(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("GOMP_SPINCOUNT", kGompSpinCount, 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only if that failed: run on with libgomp's default
  unsetenv("GOMP_SPINCOUNT");
}

}  // namespace
}  // namespace dpdrng::cli

int main(int argc, char** argv) {
  dpdrng::cli::bound_openmp_spin(argv);
  dpdrng::study::init_libraries();
  CLI::App app{"dpdrng: how cheap may the per-pair random numbers of a DPD simulation be?\n"
               "Hash generators, statistical tests, a DPD engine and a study driver in one tool.",
               "dpdrng"};
  app.set_version_flag("--version", std::string("dpdrng ") + dpdrng::kVersion);
  app.require_subcommand(1);
  app.fallthrough(false);
  auto& list = dpdrng::cli::commands();
  std::stable_sort(list.begin(), list.end(), [](auto& a, auto& b) { return a.first < b.first; });
  try {
    for (auto& [order, attach] : list) attach(app);
    dpdrng::cli::require_checked_numbers(app);
  } catch (const std::exception& e) {
    std::cerr << "dpdrng: internal error: " << e.what() << "\n";
    return dpdrng::kExitInternal;
  }
  try {
    app.parse(argc, argv);
    dpdrng::flush_standard_output();
  } catch (const CLI::CallForHelp& e) {
    return dpdrng::cli::exit_with_text(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return dpdrng::cli::exit_with_text(app, e);
  } catch (const CLI::CallForVersion& e) {
    return dpdrng::cli::exit_with_text(app, e);
  } catch (const CLI::RequiredError& e) {
    const std::string what = e.what();
    std::cerr << "dpdrng: " << (what.rfind("A subcommand", 0) == 0 ? dpdrng::cli::subcommand_message(app) : what)
              << " (see --help)\n";
    return dpdrng::kExitBadInput;
  } catch (const CLI::ParseError& e) {
    std::cerr << "dpdrng: " << e.what() << " (see --help)\n";
    return dpdrng::kExitBadInput;
  } catch (const dpdrng::InputError& e) {
    std::cerr << "dpdrng: " << e.what() << "\n";
    return dpdrng::kExitBadInput;
  } catch (const dpdrng::OutputError& e) {
    std::cerr << "dpdrng: write error: " << e.what() << "\n";
    return dpdrng::kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "dpdrng: internal error: " << e.what() << "\n";
    return dpdrng::kExitInternal;
  }
  return dpdrng::kExitOk;
}
