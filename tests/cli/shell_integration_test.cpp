// `rtpro completion bash` and `rtpro manpage`: generated from the option definitions, so each
// lists every option `--help` does, and the completion really completes in bash.
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

namespace rtpro {
namespace shell_integration_test {

using test::rtpro_command;
using test::run_command;

std::string output_of(const std::string& command_line) {
  std::string out;
  EXPECT_EQ(run_command(command_line, &out), 0) << command_line << "\n" << out;
  return out;
}

std::set<std::string> long_options_in_help(const std::string& command) {
  const std::string help = output_of(rtpro_command(command + " --help"));
  std::set<std::string> options;
  const std::regex option("(^|[ ,])(--[a-z][a-z0-9-]*)");
  for (auto it = std::sregex_iterator(help.begin(), help.end(), option); it != std::sregex_iterator(); ++it)
    options.insert((*it)[2]);
  return options;
}

// What bash offers for the words typed so far (the last one is being completed).
std::string complete(const std::filesystem::path& script, const std::string& words) {
  return output_of("bash -c 'source " + script.string() + "; COMP_WORDS=(" + words +
                   "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _rtpro; echo \"${COMPREPLY[@]}\"'");
}

TEST(ShellIntegration, BashCompletionCompletesCommandsOptionsAndValues) {
  const auto script = test::scratch_dir() / "rtpro.bash";
  output_of(rtpro_command("completion bash > " + script.string()));
  output_of("bash -n " + script.string());
  EXPECT_EQ(complete(script, "rtpro ren"), "render\n");
  EXPECT_EQ(complete(script, "rtpro render --sp"), "--spp\n");
  EXPECT_EQ(complete(script, "rtpro render --backend \\\"\\\""), "native embree\n");
  EXPECT_EQ(complete(script, "rtpro render --progress j"), "json\n");
  std::string all = complete(script, "rtpro render --");
  all.back() = ' ';  // every option followed by a space
  for (const std::string& option : long_options_in_help("render")) {
    if (option == "--display") continue;  // the deprecated spelling is hidden
    EXPECT_NE(all.find(option + " "), std::string::npos) << option << " not offered: " << all;
  }
}

TEST(ShellIntegration, ManPageDocumentsEveryOptionAndIsValidRoff) {
  const auto page = test::scratch_dir() / "rtpro.1";
  output_of(rtpro_command("manpage > " + page.string()));
  std::string text = output_of("cat " + page.string());
  text = std::regex_replace(text, std::regex(R"(\\-)"), "-");
  EXPECT_EQ(text.rfind(".TH RTPRO 1", 0), 0u);
  for (const char* command : {"render", "info", "compare", "crosscheck"}) {
    EXPECT_NE(text.find(std::string(".SS ") + command), std::string::npos) << command;
    for (const std::string& option : long_options_in_help(command)) {
      if (option == "--display" || option == "--version") continue;
      EXPECT_NE(text.find("\\fB" + option + "\\fR"), std::string::npos) << command << " " << option;
    }
  }
  std::string warnings;
  if (run_command("command -v groff >/dev/null") != 0) GTEST_SKIP() << "groff is not installed";
  EXPECT_EQ(run_command("groff -man -Tascii -ww -z " + page.string(), &warnings), 0) << warnings;
  EXPECT_EQ(warnings, "");
}

}  // namespace shell_integration_test
}  // namespace rtpro
