// rtpro's command line: subcommands register themselves (see cli/command.h); main parses,
// runs the chosen action and maps rtpro's error kinds to exit codes.
#include "command.h"
#include "usage_check.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/image/image_layer.h"

#include <embree3/rtcore_config.h>
#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/oiioversion.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

std::string version_text() {
  return std::string("rtpro ") + RTPRO_VERSION + " (Embree " + RTC_VERSION_STRING + ", OpenImageIO " +
         OIIO_VERSION_STRING + ", OpenColorIO " + OCIO_NAMESPACE::GetVersion() + ")";
}

int run(const rtpro::cli::Action& action) {
  try {
    return action ? action() : rtpro::kExitInputError;
  } catch (const rtpro::InputError& e) {
    std::cerr << "rtpro: error: " << e.what() << "\n";
    return rtpro::kExitInputError;
  } catch (const rtpro::RuntimeError& e) {
    std::cerr << "rtpro: error: " << e.what() << "\n";
    return rtpro::kExitRuntimeFailure;
  } catch (const std::bad_alloc&) {
    std::cerr << "rtpro: error: out of memory\n";
    return rtpro::kExitRuntimeFailure;
  } catch (const std::exception& e) {
    // A library's message may quote input too.
    std::cerr << "rtpro: error: " << rtpro::printable_message(e.what()) << "\n";
    return rtpro::kExitRuntimeFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rtpro: a production-style CPU ray tracer"};
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  app.fallthrough(false);

  rtpro::cli::Action action;
  rtpro::cli::add_render_command(app, action);
  rtpro::cli::add_compare_command(app, action);
  rtpro::cli::add_crosscheck_command(app, action);
  rtpro::cli::add_info_command(app, action);
  rtpro::cli::add_denoise_command(app, action);
  rtpro::cli::add_shell_integration_commands(app, action);

  const std::vector<std::string> args(argv, argv + argc);
  try {
    rtpro::cli::check_command_line(app, args);
    app.parse(argc, argv);
  } catch (const rtpro::InputError& e) {
    std::cerr << "rtpro: error: " << e.what() << "\n";
    return rtpro::kExitInputError;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 uses its own codes (e.g. 105 for validation) and two lines; usage errors are one
    // line and exit 2 by custom.
    std::cerr << rtpro::cli::usage_error_line(app, args, e.what()) << "\n";
    return rtpro::kExitInputError;
  }

  const int code = run(action);
  // A render that failed early may still be loading the image layer in the background; exit()
  // would wait for that load (about half a second) before the error reaches the user.
  if (rtpro::image_layer_loading()) {
    std::cout.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}
