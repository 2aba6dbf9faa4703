#pragma once
// Running programs from a test, above all the rtpro binary, and reading what they answer.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::test {

// Runs a shell command line; returns its exit code, and stderr+stdout in `output`.
int run_command(const std::string& command_line, std::string* output = nullptr);

// The rtpro binary followed by `args`: a command line for run_command.
std::string rtpro_command(const std::string& args);
// Runs rtpro with `args` and expects exit code `code` (a mismatch fails the test, showing the
// arguments and the output); returns stderr+stdout.
std::string run_rtpro(const std::string& args, int code);

// run_rtpro, expecting also `text` somewhere in what rtpro says (its answer: a message, a
// warning, a figure).
std::string expect_rtpro_answer(const std::string& args, int code, const std::string& text);

// `render SCENE -o OUTPUT OPTIONS`: the arguments of a render, for run_rtpro and rtpro_command.
std::string render_args(const std::filesystem::path& scene, const std::filesystem::path& output,
                        const std::string& options = "");

// Starts `argv` (argv[0]: the program's path) in a child process and returns its PID without
// waiting for it, for tests that signal a run at a chosen moment.
pid_t start_program(const std::vector<std::string>& argv);

// A PID that is certainly not running: a child that has exited and been reaped.
pid_t dead_pid();

}  // namespace rtpro::test
