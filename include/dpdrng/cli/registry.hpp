#pragma once
// Each subcommand lives in its own src/cli/cmd_*.cpp and registers itself here with a static object,
// so adding a subcommand never touches the command line itself (run.cpp).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace dpdrng::cli {

using Attach = std::function<void(CLI::App& root)>;

// `order` sorts the subcommands in --help; attach adds the subcommand (and its callback) to the root app.
bool register_command(int order, Attach attach);

// Every subcommand calls begin_work() once its options are checked, before it reads an input, writes a file or
// computes. A normal run goes on; in validate-only mode (run_cli, --validate-only) the command ends there, valid,
// by throwing ArgumentsValid, which derives from no standard exception so that no command's handler catches it.
void begin_work();
struct ArgumentsValid {};
void set_validate_only(bool on);
bool validate_only();

// Nested groups (`bench rng`, `nist runs`, `study run`) share a parent created by whichever file comes first.
CLI::App& group(CLI::App& root, const std::string& name, const std::string& description);

}  // namespace dpdrng::cli
