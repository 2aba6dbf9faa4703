// Build-time tool: asks OpenImageIO which output names it can write and prints them as C++ source
// (generated/oiio_output_formats.cpp, declared in oiio_output_formats.h). rtpro checks an output
// file name against that list before a render without loading OpenImageIO, whose ~260 shared
// libraries take about half a second to load. The list is what OpenImageIO itself answers, so it
// follows the installed library instead of a hand-written copy.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

namespace {

// "openexr:exr,sxr;tiff:tif,tiff;..." -> every format name and every extension.
std::set<std::string> candidate_names(const std::string& extension_list) {
  std::set<std::string> names;
  std::istringstream formats(extension_list);
  std::string format;
  while (std::getline(formats, format, ';')) {
    const auto colon = format.find(':');
    names.insert(format.substr(0, colon));
    if (colon == std::string::npos) continue;
    std::istringstream extensions(format.substr(colon + 1));
    std::string extension;
    while (std::getline(extensions, extension, ',')) names.insert(extension);
  }
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " OUTPUT.cpp\n";
    return 2;
  }
  // The same question write_image asks: whether ImageOutput::create accepts a file of that name.
  std::set<std::string> writable;
  for (const std::string& name : candidate_names(OIIO::get_string_attribute("extension_list")))
    if (OIIO::ImageOutput::create("probe." + name)) writable.insert(name);
  OIIO::geterror();  // the refused probes leave error text behind
  if (writable.empty()) {
    std::cerr << argv[0] << ": OpenImageIO reports no writable format\n";
    return 1;
  }

  std::ostringstream source;
  source << "// Generated at build time by generate_oiio_output_formats from OpenImageIO " << OIIO_VERSION_STRING
         << ":\n// the lowercase extensions (and format names) ImageOutput::create accepts.\n"
         << "#include \"oiio_output_formats.h\"\n\n#include <array>\n\nnamespace rtpro {\n\nnamespace {\n"
         << "constexpr std::array<std::string_view, " << writable.size() << "> kNames = {\n";
  for (const std::string& name : writable) source << "    \"" << name << "\",\n";
  source << "};\n}  // namespace\n\nconst std::span<const std::string_view> kOiioOutputExtensions(kNames);\n\n"
         << "}  // namespace rtpro\n";

  // Rewritten only when the text changes, so a rebuild does not recompile what depends on it.
  const std::string text = source.str();
  {
    std::ifstream existing(argv[1], std::ios::binary);
    std::ostringstream old;
    old << existing.rdbuf();
    if (existing && old.str() == text) return 0;
  }
  std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
  out << text;
  return out.good() ? 0 : 1;
}
