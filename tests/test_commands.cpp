#include "test_commands.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

namespace rtpro::test {

int run_command(const std::string& command_line, std::string* output) {
  const std::string full = command_line + " 2>&1";
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  std::string text;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) text += buffer.data();
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string rtpro_command(const std::string& args) { return rtpro_executable().string() + " " + args; }

std::string run_rtpro(const std::string& args, int code) {
  std::string out;
  EXPECT_EQ(run_command(rtpro_command(args), &out), code) << args << "\n" << out;
  return out;
}

std::string expect_rtpro_answer(const std::string& args, int code, const std::string& text) {
  const std::string out = run_rtpro(args, code);
  EXPECT_NE(out.find(text), std::string::npos) << "'" << text << "' not in the answer to " << args << ":\n" << out;
  return out;
}

std::string render_args(const std::filesystem::path& scene, const std::filesystem::path& output,
                        const std::string& options) {
  return "render " + scene.string() + " -o " + output.string() + (options.empty() ? "" : " " + options);
}

pid_t start_program(const std::vector<std::string>& argv) {
  std::vector<std::string> copy = argv;
  std::vector<char*> args;
  for (std::string& arg : copy) args.push_back(arg.data());
  args.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return child;
}

pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

}  // namespace rtpro::test
