#pragma once
// Each `rtpro` subcommand lives in its own file and registers itself on the CLI11 app. When the
// subcommand is chosen, its callback stores the action main() runs after parsing; actions return
// an exit code and may throw InputError (exit 2) or RuntimeError (exit 1).
#include <CLI/CLI.hpp>

#include <functional>

namespace rtpro::cli {

using Action = std::function<int()>;

void add_render_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_crosscheck_command(CLI::App& app, Action& action);
void add_info_command(CLI::App& app, Action& action);
void add_denoise_command(CLI::App& app, Action& action);
// `completion` and `manpage`, generated from the commands registered before them.
void add_shell_integration_commands(CLI::App& app, Action& action);

}  // namespace rtpro::cli
