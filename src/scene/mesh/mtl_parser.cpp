#include "mtl_parser.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "mapped_file.h"
#include "mesh_text_encoding.h"
#include "path_containment.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <optional>

namespace rtpro {

using ascii::skip_blanks;
using ascii::skip_word;
using ascii::word_at;

namespace {

struct Ignored {
  int count = 0;
  int first_line = 0;
};

class MtlParser {
 public:
  explicit MtlParser(const std::filesystem::path& file) : path_(file), file_(file.string()) {}

  MaterialLibrary parse(std::string_view text) {
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p != end) {
      const char* newline = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
      const char* line_end = newline ? newline : end;
      ++line_;
      line_begin_ = p;
      parse_line(p, line_end);
      p = newline ? newline + 1 : end;
    }
    finish_material();
    for (const auto& [keyword, ignored] : ignored_)
      library_.warnings.push_back(file_ + ":" + std::to_string(ignored.first_line) + ": ignored " +
                                  ascii::quoted(keyword) + " (" + std::to_string(ignored.count) +
                                  " in total): rtpro reads newmtl, Kd, Ks, Ns, d, Tr, map_Kd");
    return std::move(library_);
  }

 private:
  void parse_line(const char* p, const char* end) {
    p = skip_blanks(p, end);
    if (p == end || *p == '#') return;
    const std::string_view keyword = word_at(p, end);
    const char* rest = skip_blanks(p + keyword.size(), end);
    if (keyword == "newmtl") return start_material(rest, end);
    if (keyword == "Kd" || keyword == "Ks" || keyword == "Ns" || keyword == "d" || keyword == "Tr" ||
        keyword == "map_Kd") {
      if (unnamed_) return;  // the statements of a nameless material: no face can use it
      if (!current_) fail(p, std::string(keyword) + " before any newmtl");
      if (keyword == "Kd") current_->color = colour(rest, end, keyword);
      if (keyword == "Ks") {
        const Color ks = colour(rest, end, keyword);
        ks_ = (ks.x + ks.y + ks.z) / 3.0f;
      }
      if (keyword == "Ns") ns_ = numbers(rest, end, 1, keyword).values[0];
      if (keyword == "d") current_->opacity = fraction(rest, end, keyword);
      if (keyword == "Tr") current_->opacity = 1.0f - fraction(rest, end, keyword);
      if (keyword == "map_Kd") texture(rest, end);
      return;
    }
    Ignored& ignored = ignored_[std::string(keyword)];
    if (ignored.count++ == 0) ignored.first_line = line_;
  }

  void start_material(const char* p, const char* end) {
    finish_material();
    while (end != p && ascii::is_blank(end[-1])) --end;
    // Blender writes a bare `newmtl` (and a bare `usemtl`) for faces without a material; those
    // faces get the default material, so this definition is not used.
    unnamed_ = p == end;
    if (unnamed_) {
      library_.warnings.push_back(
          file_ + ":" + std::to_string(line_) +
          ": newmtl without a name: ignored (faces after a bare usemtl use the default material)");
      return;
    }
    current_ = MaterialDesc{};
    current_->name.assign(p, end);
    ks_ = PhongParams{}.specular;
    ns_ = PhongParams{}.shininess;
    material_line_ = line_;
  }

  void finish_material() {
    if (!current_) return;
    PhongParams phong;
    phong.shininess = std::max(ns_, 1.0f);
    phong.specular = ks_ * std::min(1.0f, ns_ / kFullHighlightNs);
    current_->params = phong;
    if (current_->opacity < 1.0f)
      library_.warnings.push_back(file_ + ":" + std::to_string(material_line_) + ": material " +
                                  ascii::quoted(current_->name) + " is partly transparent (d " +
                                  std::to_string(current_->opacity) + "); rtpro renders it opaque");
    for (const MaterialDesc& m : library_.materials) {
      if (m.name == current_->name) {
        library_.warnings.push_back(file_ + ": material " + ascii::quoted(m.name) +
                                    " is defined twice; the first one is used");
        current_.reset();
        return;
      }
    }
    library_.materials.push_back(std::move(*current_));
    current_.reset();
  }

  float fraction(const char* p, const char* end, std::string_view keyword) {
    const float value = numbers(p, end, 1, keyword).values[0];
    if (value > 1.0f) fail(p, std::string(keyword) + " must be from 0 to 1, found " + ascii::quoted(word_at(p, end)));
    return value;
  }

  // `map_Kd [-options ...] file`: the file is the last word. `\` separates folders as `/` does
  // (files written on Windows say `.\tex.jpg`; Blender and assimp read them so). A texture that
  // is not there is a warning and the material keeps its Kd; one reached through a symbolic link
  // outside the library's folder is refused, as mtllib is.
  void texture(const char* p, const char* end) {
    while (end != p && ascii::is_blank(end[-1])) --end;
    const char* name = end;
    while (name != p && !ascii::is_blank(name[-1])) --name;
    const std::string_view written(name, std::size_t(end - name));
    if (written.empty()) fail(p, "map_Kd needs a file name");
    std::string slashed(written);
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    const std::filesystem::path relative(slashed);
    const std::filesystem::path normal = relative.lexically_normal();
    if (relative.is_absolute() || relative.has_root_name() || normal.empty() || *normal.begin() == ".." ||
        (slashed.size() >= 2 && slashed[1] == ':')) {  // C:/... written on Windows
      library_.warnings.push_back(file_ + ":" + std::to_string(line_) + ": texture " + ascii::quoted(written) +
                                  " is not inside the material library's folder; ignored");
      return;
    }
    const std::filesystem::path path = path_.parent_path() / normal;
    if (!resolves_inside(path_.parent_path(), path))
      fail(name, "texture " + ascii::quoted(written) +
                     " leads outside the material library's folder (through a symbolic link)");
    std::error_code not_readable;
    if (!std::filesystem::is_regular_file(path, not_readable)) {
      library_.warnings.push_back(file_ + ":" + std::to_string(line_) + ": texture " + ascii::quoted(written) +
                                  " not found; material " + ascii::quoted(current_->name) + " uses its Kd colour");
      return;
    }
    current_->color_texture = path;
    current_->texture_where = SourceLocation{file_, static_cast<int>(line_), 0};
  }

  // "r g b", or a single "r" meaning grey as the MTL specification allows.
  Color colour(const char* p, const char* end, std::string_view keyword) {
    const Numbers n = numbers(p, end, 3, keyword);
    if (n.count == 2) fail(p, std::string(keyword) + " needs 1 or 3 numbers, found 2");
    return n.count == 1 ? Color(n.values[0]) : Color(n.values[0], n.values[1], n.values[2]);
  }

  struct Numbers {
    std::array<float, 3> values{};
    int count = 0;
  };

  // 1 to `most` non-negative finite numbers, then the end of the line.
  Numbers numbers(const char* p, const char* end, int most, std::string_view keyword) {
    Numbers n;
    for (p = skip_blanks(p, end); p != end && *p != '#'; p = skip_blanks(skip_word(p, end), end)) {
      if (n.count == most) fail(p, "unexpected " + ascii::quoted(word_at(p, end)) + " after " + std::string(keyword));
      float value = 0.0f;
      const ascii::FloatScan scan = ascii::scan_real(p, end, value);
      if (scan.status != ascii::NumberStatus::kOk || value < 0.0f)
        fail(p, std::string(keyword) + " needs non-negative finite numbers, found " + ascii::quoted(word_at(p, end)));
      n.values[std::size_t(n.count++)] = value;
    }
    if (n.count == 0) fail(p, std::string(keyword) + " needs a number");
    return n;
  }

  [[noreturn]] void fail(const char* at, const std::string& message) const {
    throw InputError(SourceLocation{file_, line_, int(at - line_begin_) + 1}, message);
  }

  std::filesystem::path path_;
  std::string file_;
  int line_ = 0;
  int material_line_ = 0;
  bool unnamed_ = false;
  float ks_ = 0.0f, ns_ = 0.0f;  // of the current material, mapped when it is complete
  const char* line_begin_ = nullptr;
  std::optional<MaterialDesc> current_;
  std::map<std::string, Ignored> ignored_;  // ordered: warnings come out the same every time
  MaterialLibrary library_;
};

}  // namespace

MaterialLibrary parse_mtl_file(const std::filesystem::path& file) {
  const MappedFile bytes(file);
  require_narrow_text(bytes.text(), file.string(), "MTL");
  return MtlParser(file).parse(without_utf8_bom(bytes.text()));
}

}  // namespace rtpro
