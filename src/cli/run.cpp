// The command line as a function (run.hpp): builds the app from the registry, parses, and maps every error to an
// exit code with a one-line message.
#include "dpdrng/cli/run.hpp"

#include <algorithm>
#include <iostream>

#include "dpdrng/cli/checked.hpp"
#include "dpdrng/cli/registry.hpp"
#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"
#include "dpdrng/common/output.hpp"
#include "dpdrng/version.hpp"

namespace dpdrng::cli {
std::vector<std::pair<int, Attach>>& commands();

namespace entry {
namespace {

// Every message goes through printable(): it may echo anything typed on the command line or read from a file.
int fail(int code, const std::string& what, const char* tail = "") {
  std::cerr << "dpdrng: " << printable(what) << tail << "\n";
  return code;
}

// Help and version text go to standard output like any result: a lost one is a write error.
int exit_with_text(CLI::App& app, const CLI::ParseError& e) {
  const int code = app.exit(e);
  try {
    flush_standard_output();
  } catch (const OutputError& err) {
    return fail(kExitInternal, std::string("write error: ") + err.what());
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
  if (!extra.empty()) return "unknown command " + quote_input(extra.front()) + " for " + path + " (known: " + names + ")";
  return path + " needs a command (one of: " + names + ")";
}

// Parses and runs; every exception a command may throw becomes its exit code here.
int parse_and_run(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    flush_standard_output();
  } catch (const ArgumentsValid&) {
    return kExitOk;
  } catch (const CLI::CallForHelp& e) {
    return exit_with_text(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return exit_with_text(app, e);
  } catch (const CLI::CallForVersion& e) {
    return exit_with_text(app, e);
  } catch (const CLI::RequiredError& e) {
    const std::string what = e.what();
    return fail(kExitBadInput, what.rfind("A subcommand", 0) == 0 ? subcommand_message(app) : what, " (see --help)");
  } catch (const CLI::ParseError& e) {
    return fail(kExitBadInput, e.what(), " (see --help)");
  } catch (const InputError& e) {
    return fail(kExitBadInput, e.what());
  } catch (const OutputError& e) {
    return fail(kExitInternal, std::string("write error: ") + e.what());
  } catch (const std::exception& e) {
    return fail(kExitInternal, std::string("internal error: ") + e.what());
  }
  // Every subcommand stops at begin_work() when only validating: one that got past it did real work.
  if (validate_only()) return fail(kExitInternal, "internal error: a command ran without checking its arguments first");
  return kExitOk;
}

}  // namespace
}  // namespace entry

std::unique_ptr<CLI::App> make_app() {
  auto app = std::make_unique<CLI::App>(
      "dpdrng: how cheap may the per-pair random numbers of a DPD simulation be?\n"
      "Hash generators, statistical tests, a DPD engine and a study driver in one tool.",
      "dpdrng");
  app->set_version_flag("--version", std::string("dpdrng ") + kVersion);
  app->add_flag_callback("--validate-only", [] { set_validate_only(true); },
                         "check the arguments and exit: 0 valid, 2 invalid (reads no input, writes nothing)");
  app->require_subcommand(1);
  app->fallthrough(false);
  auto& list = commands();
  std::stable_sort(list.begin(), list.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (auto& [order, attach] : list) attach(*app);
  require_checked_numbers(*app);
  return app;
}

int run_cli(int argc, char** argv, RunMode mode) {
  set_validate_only(mode == RunMode::validate_only);
  std::unique_ptr<CLI::App> app;
  try {
    app = make_app();
  } catch (const std::exception& e) {
    return entry::fail(kExitInternal, std::string("internal error: ") + e.what());
  }
  const int code = entry::parse_and_run(*app, argc, argv);
  set_validate_only(false);
  return code;
}

}  // namespace dpdrng::cli
