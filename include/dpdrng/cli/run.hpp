#pragma once
// The whole command line as a function: every registered subcommand, the parse, and the mapping of errors to the
// exit codes of dpdrng/common/error.hpp. main() and the argument fuzzer both call it.
#include <CLI/CLI.hpp>
#include <memory>

namespace dpdrng::cli {

// validate_only: each subcommand checks its options as for a real run (ranges, contradictions, a config file it
// names) and stops before reading an input, writing a file or computing (registry.hpp, begin_work).
enum class RunMode { run, validate_only };

// The root app with every registered subcommand attached; throws std::logic_error for a numeric option that
// bypasses the checked-number parser.
std::unique_ptr<CLI::App> make_app();

// The exit code: kExitOk, kExitBadInput or kExitInternal. The global flag --validate-only selects validate_only too.
int run_cli(int argc, char** argv, RunMode mode);

}  // namespace dpdrng::cli
