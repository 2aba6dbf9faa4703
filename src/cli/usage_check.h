#pragma once
// Usage errors found before CLI11 parses: an unknown subcommand or option with the nearest valid
// one suggested, and single-value options given twice. CLI11's own messages for these ("The
// following arguments were not expected: 4 --sp", "At Most 1 required but received 2") name no
// alternative; these are one line each and end in exit code 2 like every input error.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rtpro::cli {

// Whether the option reads a value (not a flag).
inline bool takes_value(const CLI::Option& option) { return option.get_items_expected_max() > 0; }

// Throws InputError for the first problem in argv (argv[0] is the program).
void check_command_line(const CLI::App& app, const std::vector<std::string>& args);

// "rtpro: error: ..." for an error CLI11 found itself, with the subcommand's help pointer.
std::string usage_error_line(const CLI::App& app, const std::vector<std::string>& args, const std::string& message);

}  // namespace rtpro::cli
