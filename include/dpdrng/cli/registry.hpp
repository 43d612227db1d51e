#pragma once
// Each subcommand lives in its own src/cli/cmd_*.cpp and registers itself here with a static object,
// so adding a subcommand never touches main.cpp.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace dpdrng::cli {

using Attach = std::function<void(CLI::App& root)>;

// `order` sorts the subcommands in --help; attach adds the subcommand (and its callback) to the root app.
bool register_command(int order, Attach attach);

// Nested groups (`bench rng`, `nist runs`, `study run`) share a parent created by whichever file comes first.
CLI::App& group(CLI::App& root, const std::string& name, const std::string& description);

}  // namespace dpdrng::cli
