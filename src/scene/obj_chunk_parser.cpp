#include "rtpro/core/error.h"
#include "rtpro/scene/ascii_scan.h"
#include "rtpro/scene/mesh_limits.h"
#include "rtpro/scene/obj_chunk.h"

#include <cmath>
#include <string>
#include <unordered_map>

namespace rtpro::obj {

using ascii::is_blank;
using ascii::quoted;
using ascii::skip_blanks;
using ascii::skip_word;
using ascii::word_at;

namespace {

inline constexpr std::uint32_t kNoIndex = ~0u;

// Calls visit(begin, end) for every line of text, without its '\n'.
template <typename Visit>
void for_each_line(std::string_view text, Visit&& visit) {
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p != end) {
    const char* line_end = ascii::find_line_end(p, end);
    visit(p, line_end);
    p = line_end == end ? end : line_end + 1;
  }
}

// The statement keyword of a line ("v", "f", ...); empty for blank and comment lines.
std::string_view keyword_of(const char* p, const char* end) {
  p = skip_blanks(p, end);
  if (p == end || *p == '#') return {};
  return word_at(p, end);
}

// A line's text after its keyword, without surrounding blanks.
std::string_view argument_text(const char* p, const char* end) {
  p = skip_blanks(p, end);
  while (end != p && is_blank(end[-1])) --end;
  return {p, std::size_t(end - p)};
}

struct Corner {
  std::uint32_t position;
  std::uint32_t normal;  // kNoIndex without one
};

class ChunkParser {
 public:
  ChunkParser(Chunk& chunk, const Destination& out) : chunk_(chunk), out_(out), seen_(chunk.start) {}

  void parse() {
    chunk_.triangle_positions.reserve(chunk_.counts.faces);  // exact when every face is a triangle
    for_each_line(chunk_.text, [this](const char* begin, const char* end) {
      line_begin_ = begin;
      ++seen_.lines;
      parse_line(begin, end);
    });
  }

 private:
  void parse_line(const char* p, const char* end) {
    const std::string_view keyword = keyword_of(p, end);
    if (keyword.empty()) return;
    const char* rest = skip_blanks(keyword.data() + keyword.size(), end);
    if (keyword == "v") return parse_position(rest, end);
    if (keyword == "f") return parse_face(rest, end);
    if (keyword == "vn") return parse_normal(rest, end);
    if (keyword == "vt") return parse_texcoord(rest, end);
    if (keyword == "s") return parse_smoothing(rest, end);
    if (keyword == "usemtl") return parse_usemtl(rest, end);
    if (keyword == "mtllib") return parse_mtllib(rest, end);
    if (keyword == "o") return parse_object_name(rest, end);
    if (keyword == "g") return;  // groups name parts of one mesh: nothing to keep
    tally_ignored(keyword);
  }

  void parse_position(const char* p, const char* end) {
    float xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      p = skip_blanks(p, end);
      if (at_line_end(p, end)) fail(p, "vertex needs 3 coordinates, found " + std::to_string(axis));
      xyz[axis] = number(p, end);
      if (!(std::fabs(xyz[axis]) <= kMaxAbsCoordinate))
        fail(p, "coordinate " + std::string(word_at(p, end)) + " is beyond the supported magnitude 1e16");
      p = skip_word(p, end);
    }
    // A 4th number is the rational weight w, 3 more a vertex colour (a common extension):
    // validated, not used.
    expect_numbers_then_end(p, end, 3, "after the vertex coordinates");
    out_.positions[seen_.positions++] = PaddedVertex{xyz[0], xyz[1], xyz[2], 0.0f};
  }

  void parse_normal(const char* p, const char* end) {
    float xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      p = skip_blanks(p, end);
      if (at_line_end(p, end)) fail(p, "normal needs 3 components, found " + std::to_string(axis));
      xyz[axis] = number(p, end);
      p = skip_word(p, end);
    }
    expect_numbers_then_end(p, end, 0, "after the normal");
    if (xyz[0] == 0.0f && xyz[1] == 0.0f && xyz[2] == 0.0f && chunk_.first_zero_normal_line == 0)
      chunk_.first_zero_normal_line = seen_.lines;
    out_.normals[seen_.normals++] = Vec3(xyz[0], xyz[1], xyz[2]);
  }

  void parse_texcoord(const char* p, const char* end) {
    if (at_line_end(skip_blanks(p, end), end)) fail(p, "texture coordinate needs 1 to 3 numbers");
    expect_numbers_then_end(p, end, 3, "after the texture coordinate");
    ++seen_.texcoords;
  }

  void parse_face(const char* p, const char* end) {
    corners_.clear();
    for (p = skip_blanks(p, end); !at_line_end(p, end); p = skip_blanks(p, end)) corners_.push_back(corner(p, end));
    if (corners_.size() < 3)
      fail(line_begin_, "face needs at least 3 vertices, found " + std::to_string(corners_.size()));
    ++chunk_.faces;
    keep_normals_while_complete();
    // Fan triangulation: exact for the convex polygons OBJ exporters write.
    for (std::size_t i = 1; i + 1 < corners_.size(); ++i) {
      const Corner& a = corners_[0];
      const Corner& b = corners_[i];
      const Corner& c = corners_[i + 1];
      if (a.position == b.position || b.position == c.position || a.position == c.position) {
        ++chunk_.dropped_degenerate;
        continue;
      }
      chunk_.triangle_positions.push_back({a.position, b.position, c.position});
      if (chunk_.every_corner_has_normal) chunk_.triangle_normals.push_back({a.normal, b.normal, c.normal});
    }
  }

  void keep_normals_while_complete() {
    if (!chunk_.every_corner_has_normal) return;
    for (const Corner& c : corners_) {
      if (c.normal == kNoIndex) {
        chunk_.every_corner_has_normal = false;
        chunk_.triangle_normals = {};
        return;
      }
    }
  }

  // One face vertex: v, v/vt, v//vn or v/vt/vn. Advances p past it.
  Corner corner(const char*& p, const char* end) {
    const char* token = p;
    Corner result{index(p, end, seen_.positions, out_.totals.positions, "vertex"), kNoIndex};
    if (p != end && *p == '/') {
      ++p;
      if (p == end || *p != '/') index(p, end, seen_.texcoords, out_.totals.texcoords, "texture coordinate");
      if (p != end && *p == '/') {
        ++p;
        result.normal = index(p, end, seen_.normals, out_.totals.normals, "normal");
      }
    }
    if (p != end && !is_blank(*p) && *p != '#') fail(token, "malformed face vertex " + quoted(word_at(token, end)));
    return result;
  }

  // A 1-based index, or a negative one relative to the `declared` elements read so far; returns
  // the 0-based index. Positive indices may point forward, up to the file's total.
  std::uint32_t index(const char*& p, const char* end, std::uint64_t declared, std::uint64_t total,
                      const char* what) {
    std::int64_t raw = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(p, end, raw);
    if (!scan.ok) fail(p, std::string("expected a ") + what + " index, found " + quoted(word_at(p, end)));
    if (raw == 0) fail(p, std::string(what) + " index 0 is invalid: OBJ indices start at 1");
    std::uint64_t resolved = 0;
    if (raw > 0) {
      if (std::uint64_t(raw) > total)
        fail(p, std::string(what) + " index " + std::to_string(raw) + " is out of range: the file has " +
                    std::to_string(total));
      resolved = std::uint64_t(raw) - 1;
    } else {
      if (std::uint64_t(-raw) > declared)
        fail(p, std::string(what) + " index " + std::to_string(raw) + " is out of range: only " +
                    std::to_string(declared) + " declared before this line");
      resolved = declared - std::uint64_t(-raw);
    }
    p = scan.next;
    return std::uint32_t(resolved);
  }

  void parse_smoothing(const char* p, const char* end) {
    const std::string_view word = word_at(p, end);
    std::uint32_t group = kFlat;
    std::int64_t number = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(p, end, number);
    if (word == "off") {
      group = kFlat;
    } else if (word == "on") {
      group = 1;  // not in the specification, but written by some exporters
    } else if (scan.ok && scan.next == word.data() + word.size() && number >= 0 &&
               std::uint64_t(number) < kInherited) {
      group = std::uint32_t(number);
    } else {
      fail(p, "expected 'off' or a smoothing group number, found " + quoted(word));
    }
    expect_numbers_then_end(skip_word(p, end), end, 0, "after the smoothing group");
    chunk_.has_smoothing_statement = true;
    change_state().smoothing = group;
  }

  void parse_usemtl(const char* p, const char* end) {
    const std::string_view name = argument_text(p, end);
    if (name.empty()) fail(p, "usemtl needs a material name");
    auto [slot, inserted] = material_slots_.try_emplace(name, std::uint32_t(chunk_.material_names.size()));
    if (inserted) chunk_.material_names.push_back({name, seen_.lines});
    change_state().material_slot = slot->second;
  }

  void parse_mtllib(const char* p, const char* end) {
    if (at_line_end(p, end)) fail(p, "mtllib needs a file name");
    for (; !at_line_end(p, end); p = skip_blanks(skip_word(p, end), end))
      chunk_.material_libraries.push_back({word_at(p, end), seen_.lines});
  }

  void parse_object_name(const char* p, const char* end) {
    if (chunk_.object_name.name.empty()) chunk_.object_name = {argument_text(p, end), seen_.lines};
  }

  // The state entry for the next triangle, carrying over what earlier statements set.
  StateChange& change_state() {
    auto& changes = chunk_.state_changes;
    const auto next_triangle = std::uint32_t(chunk_.triangle_positions.size());
    if (changes.empty()) {
      changes.push_back({next_triangle, kInherited, kInherited});
    } else if (changes.back().first_triangle != next_triangle) {
      StateChange carried = changes.back();
      carried.first_triangle = next_triangle;
      changes.push_back(carried);
    }
    return changes.back();
  }

  void tally_ignored(std::string_view keyword) {
    for (IgnoredKeyword& k : chunk_.ignored) {
      if (k.keyword == keyword) return void(++k.count);
    }
    chunk_.ignored.push_back({keyword, 1, seen_.lines});
  }

  float number(const char* p, const char* end) {
    float value = 0.0f;
    const ascii::FloatScan scan = ascii::scan_real(p, end, value);
    if (scan.status == ascii::NumberStatus::kMalformed)
      fail(p, quoted(word_at(p, end)) + " is not a number");
    if (scan.status == ascii::NumberStatus::kNotFinite)
      fail(p, quoted(word_at(p, end)) + " is not a finite number in float range");
    return value;
  }

  // Up to `allowed` more numbers (validated, unused), then the end of the line.
  void expect_numbers_then_end(const char* p, const char* end, int allowed, const char* where) {
    for (p = skip_blanks(p, end); !at_line_end(p, end); p = skip_blanks(skip_word(p, end), end)) {
      if (allowed-- == 0) fail(p, "unexpected " + quoted(word_at(p, end)) + " " + where);
      number(p, end);
    }
  }

  static bool at_line_end(const char* p, const char* end) { return p == end || *p == '#'; }

  [[noreturn, gnu::cold, gnu::noinline]] void fail(const char* at, const std::string& message) const {
    throw InputError(SourceLocation{out_.file, int(seen_.lines), int(at - line_begin_) + 1}, message);
  }

  Chunk& chunk_;
  const Destination& out_;
  Counts seen_;  // everything declared up to the current line, file-wide
  const char* line_begin_ = nullptr;
  std::vector<Corner> corners_;  // of the current face; reused to avoid an allocation per face
  std::unordered_map<std::string_view, std::uint32_t> material_slots_;
};

}  // namespace

std::vector<Chunk> split_into_chunks(std::string_view text, std::size_t chunk_bytes) {
  std::vector<Chunk> chunks;
  const std::size_t step = chunk_bytes == 0 ? 1 : chunk_bytes;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.size();
    if (text.size() - begin > step) {
      const std::size_t newline = text.find('\n', begin + step - 1);
      end = newline == std::string_view::npos ? text.size() : newline + 1;
    }
    chunks.emplace_back().text = text.substr(begin, end - begin);
    begin = end;
  }
  return chunks;
}

void count_chunk(Chunk& chunk) {
  Counts counts;
  for_each_line(chunk.text, [&counts](const char* begin, const char* end) {
    ++counts.lines;
    const std::string_view keyword = keyword_of(begin, end);
    if (keyword.size() == 1 && keyword[0] == 'v') ++counts.positions;
    else if (keyword == "vn") ++counts.normals;
    else if (keyword == "vt") ++counts.texcoords;
    else if (keyword.size() == 1 && keyword[0] == 'f') ++counts.faces;
  });
  chunk.counts = counts;
}

void parse_chunk(Chunk& chunk, const Destination& out) {
  try {
    ChunkParser(chunk, out).parse();
  } catch (const InputError&) {
    chunk.error = std::current_exception();
  }
}

}  // namespace rtpro::obj
