#include "usage_check.h"

#include "rtpro/core/closest_match.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/core/error.h"

#include <map>
#include <sstream>

namespace rtpro::cli {

namespace {

bool is_help_or_version(const std::string& arg) { return arg == "-h" || arg == "--help" || arg == "--version"; }

// A subcommand named by the first argument, or nullptr.
const CLI::App* find_subcommand(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(name)) return sub;
  return nullptr;
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_spellings(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

const CLI::Option* find_option(const CLI::App& command, const std::string& spelling) {
  for (const CLI::Option* option : command.get_options())
    if (!option->get_positional() && option->check_name(spelling)) return option;
  return nullptr;
}

std::string help_pointer(const std::string& command) {
  return " (see 'rtpro " + (command.empty() ? std::string() : command + " ") + "--help')";
}

// Other renderers' spellings of rtpro's options (pbrt-v4, Mitsuba 3, Blender, POV-Ray), for
// render: the message names rtpro's option instead of the nearest by spelling.
std::string other_renderers_name(const std::string& spelling) {
  static const std::map<std::string, std::string> kHabits = {
      {"--outfile", "-o/--output (pbrt's --outfile)"},
      {"--nthreads", "--threads (pbrt's --nthreads)"},
      {"--cropwindow", "--region x0,y0,x1,y1 in pixels (pbrt's --cropwindow takes fractions)"},
      {"--pixelbounds", "--region x0,y0,x1,y1 (pbrt's --pixelbounds)"},
      {"--samples", "--spp"},
      {"--width", "--size WIDTHxHEIGHT"},
      {"--height", "--size WIDTHxHEIGHT"},
      {"--frame", "--frames N, or -D frame=N (Blender's -f)"},
      {"--render-frame", "--frames N (Blender's -f)"},
      {"--render-anim", "--frames FIRST-LAST (Blender's -a)"},
      {"--frame-start", "--frames FIRST-LAST"},
      {"--frame-end", "--frames FIRST-LAST"},
      {"--threads-count", "--threads"},
      {"-x", "--skip-existing (Mitsuba's -x)"},
  };
  const auto found = kHabits.find(spelling);
  return found == kHabits.end() ? std::string() : found->second;
}

[[noreturn]] void unknown_option(const CLI::App& command, const std::string& spelling) {
  const std::string where = command.get_parent() ? " for 'rtpro " + command.get_name() + "'" : "";
  if (const std::string habit = other_renderers_name(spelling); !habit.empty() && command.get_name() == "render")
    throw InputError("unknown option '" + spelling + "'" + where + "; rtpro's is " + habit +
                     help_pointer(command.get_name()));
  throw InputError("unknown option '" + spelling + "'" + where + suggestion(spelling, option_spellings(command)) +
                   help_pointer(command.get_parent() ? command.get_name() : ""));
}

// Flags expect no items; options with a value one (or more, for lists).
// Options whose later values would silently replace or reject earlier ones.
bool takes_one_value(const CLI::Option& option) {
  return takes_value(option) && option.get_multi_option_policy() == CLI::MultiOptionPolicy::Throw &&
         option.get_items_expected_max() <= 1;
}

void check_options(const CLI::App& command, const std::vector<std::string>& args, std::size_t first) {
  std::map<const CLI::Option*, std::string> given;
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--") return;  // everything after it is positional
    if (arg.size() < 2 || arg[0] != '-') continue;
    const bool long_form = arg[1] == '-';
    const std::size_t equals = arg.find('=');
    const std::string spelling = long_form ? arg.substr(0, equals) : arg.substr(0, 2);
    const CLI::Option* option = find_option(command, spelling);
    if (!option) unknown_option(command, spelling);
    // "-qv": a run of short flags; "-ofile": a short option with its value attached.
    bool value_attached = long_form ? equals != std::string::npos : arg.size() > 2;
    if (!long_form && !takes_value(*option)) {
      for (std::size_t c = 2; c < arg.size(); ++c) {
        const CLI::Option* flag = find_option(command, std::string("-") + arg[c]);
        if (!flag) unknown_option(command, std::string("-") + arg[c]);
        if (takes_value(*flag)) break;
      }
      value_attached = false;
    }
    std::string value;
    if (takes_value(*option)) {
      if (value_attached) {
        value = long_form ? arg.substr(equals + 1) : arg.substr(2);
      } else if (i + 1 < args.size()) {
        value = args[++i];
      }
    }
    if (!takes_one_value(*option)) continue;
    const auto [seen, first_time] = given.emplace(option, value);
    if (!first_time)
      throw InputError(spelling + " given twice ('" + seen->second + "' and '" + value + "'); it takes one value" +
                       help_pointer(command.get_name()));
  }
}

// CLI11 lists unexpected arguments last first.
std::string in_typed_order(const std::string& reversed) {
  std::vector<std::string> words;
  std::istringstream list(reversed);
  for (std::string word; list >> word;) words.insert(words.begin(), word);
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + ("'" + word + "'");
  return text;
}

}  // namespace

void check_command_line(const CLI::App& app, const std::vector<std::string>& args) {
  if (args.size() < 2)
    throw InputError("a command is required: " + [&] {
      std::string names;
      for (const std::string& name : subcommand_names(app)) names += (names.empty() ? "" : ", ") + name;
      return names;
    }() + help_pointer(""));
  std::size_t i = 1;
  while (i < args.size() && is_help_or_version(args[i])) ++i;
  if (i == args.size()) return;
  const std::string& name = args[i];
  if (!name.empty() && name[0] == '-') unknown_option(app, name.substr(0, name.find('=')));
  const CLI::App* command = find_subcommand(app, name);
  if (!command)
    throw InputError("unknown command '" + name + "'" + suggestion(name, subcommand_names(app)) + help_pointer(""));
  check_options(*command, args, i + 1);
}

std::string usage_error_line(const CLI::App& app, const std::vector<std::string>& args, const std::string& message) {
  std::string command;
  for (std::size_t i = 1; i < args.size() && command.empty(); ++i)
    if (find_subcommand(app, args[i])) command = args[i];
  std::string text = message;
  // CLI11's words for arguments no option or positional takes, in rtpro's voice.
  for (const auto& [theirs, ours] :
       {std::pair<std::string, std::string>{"The following argument was not expected: ", "unexpected argument: "},
        {"The following arguments were not expected: ", "unexpected arguments: "}})
    if (text.rfind(theirs, 0) == 0) text = ours + in_typed_order(text.substr(theirs.size()));
  std::string line = "rtpro: error: " + text;
  while (!line.empty() && line.back() == '\n') line.pop_back();
  for (char& c : line)
    if (c == '\n') c = ' ';
  // What remains of control characters came from the command line (an option's name or value).
  return printable_message(line) + help_pointer(command);
}

}  // namespace rtpro::cli
