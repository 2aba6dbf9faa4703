#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "mesh_limits.h"
#include "obj_chunk.h"

#include <cmath>
#include <string>
#include <unordered_map>

namespace rtpro::obj {

using ascii::is_blank;
using ascii::is_word_end;
using ascii::skip_blanks;
using ascii::skip_word;
using ascii::word_at;

namespace {

// The statement keyword of the line starting at p ("v", "f", ...); empty for blank lines. Both
// passes classify lines with it, so they always agree.
std::string_view keyword_at(const char* p, const char* end) {
  p = skip_blanks(p, end);
  return word_at(p, end);
}

// Parses one chunk in a single pass: every statement handler starts after its keyword and
// returns the end of its line (the '\n' or the chunk's end), so no line is scanned twice.
class ChunkParser {
 public:
  ChunkParser(Chunk& chunk, const Destination& out)
      : chunk_(chunk), out_(out), seen_(chunk.start), end_(chunk.text.data() + chunk.text.size()) {}

  void parse() {
    for (const char* p = chunk_.text.data(); p != end_;) {
      line_begin_ = p;
      ++seen_.lines;
      p = parse_line(p);
      if (p != end_) ++p;
    }
  }

 private:
  const char* parse_line(const char* p) {
    const std::string_view keyword = keyword_at(p, end_);
    const char* rest = skip_blanks(keyword.data() + keyword.size(), end_);
    if (keyword == "v") return parse_position(rest);
    if (keyword == "f") return parse_face(rest);
    if (keyword.empty() || keyword[0] == '#') return ascii::find_line_end(rest, end_);
    if (keyword == "vn") return parse_normal(rest);
    if (keyword == "vt") return parse_texcoord(rest);
    if (keyword == "s") return parse_smoothing(rest);
    if (keyword == "usemtl") return parse_usemtl(rest);
    if (keyword == "mtllib") return parse_mtllib(rest);
    if (keyword == "o") return parse_object_name(rest);
    if (keyword != "g") tally_ignored(keyword);  // g names parts of one mesh: nothing to keep
    return ascii::find_line_end(rest, end_);
  }

  // parse_position, parse_face and corner are forced inline into the line loop, and the rare
  // paths (extra numbers, polygons, attribute bookkeeping) kept out of it: left to the compiler,
  // the calls per vertex and corner cost about 15% of the dragon's parse.
  [[gnu::always_inline]] const char* parse_position(const char* p) {
    float xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      p = skip_blanks(p, end_);
      if (at_line_end(p)) fail(p, "vertex needs 3 coordinates, found " + std::to_string(axis));
      const char* number_begin = p;
      p = number(p, xyz[axis]);
      if (!(std::fabs(xyz[axis]) <= kMaxAbsCoordinate))
        fail(number_begin,
             "coordinate " + std::string(word_at(number_begin, end_)) + " is beyond the supported magnitude 1e16");
    }
    const std::uint32_t position = std::uint32_t(seen_.positions++);
    out_.positions[position] = MeshVertex{xyz[0], xyz[1], xyz[2]};
    p = skip_blanks(p, end_);
    if (at_line_end(p)) return line_end(p);  // the common case: nothing more
    // A 4th number is the rational weight w (validated, unused), 3 more a vertex colour (a common
    // extension that Blender, MeshLab and assimp read).
    return parse_position_extras(p, position);
  }

  [[gnu::noinline]] const char* parse_position_extras(const char* p, std::uint32_t position) {
    float extra[3];
    const int extras = numbers_into(p, extra, "after the vertex coordinates");
    if (extras == 3) chunk_.colors.push_back({position, Color(extra[0], extra[1], extra[2])});
    return line_end(skip_blanks(p, end_));
  }

  const char* parse_normal(const char* p) {
    float xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      p = skip_blanks(p, end_);
      if (at_line_end(p)) fail(p, "normal needs 3 components, found " + std::to_string(axis));
      p = number(p, xyz[axis]);
    }
    if (xyz[0] == 0.0f && xyz[1] == 0.0f && xyz[2] == 0.0f && chunk_.first_zero_normal_line == 0)
      chunk_.first_zero_normal_line = seen_.lines;
    out_.normals[seen_.normals++] = Vec3(xyz[0], xyz[1], xyz[2]);
    return numbers_then_line_end(p, 0, "after the normal");
  }

  const char* parse_texcoord(const char* p) {
    if (at_line_end(p)) fail(p, "texture coordinate needs 1 to 3 numbers");
    float uvw[3] = {0.0f, 0.0f, 0.0f};
    numbers_into(p, uvw, "after the texture coordinate");
    out_.texcoords[seen_.texcoords++] = TexCoord{uvw[0], uvw[1]};
    return line_end(skip_blanks(p, end_));
  }

  // A triangle goes to its slot at once. A polygon waits in the chunk until every position of
  // the file is known: only then can a concave one be told from a convex one.
  [[gnu::always_inline]] const char* parse_face(const char* p) {
    Corner first3[3];
    std::size_t corners = 0;
    for (; corners < 3 && !at_line_end(p); p = skip_blanks(p, end_)) first3[corners++] = corner(p);
    if (corners < 3) fail(line_begin_, "face needs at least 3 vertices, found " + std::to_string(corners));
    // Attribute bookkeeping costs nothing once both kinds are known to be missing somewhere.
    if (tracking_attributes_)
      for (const Corner& c : first3) note_attributes(c);
    ++chunk_.faces;
    if (at_line_end(p)) {
      add_triangle(first3[0], first3[1], first3[2]);
      return line_end(p);
    }
    start_polygon(first3);
    for (; !at_line_end(p); p = skip_blanks(p, end_), ++corners) {
      const Corner current = corner(p);
      if (tracking_attributes_) note_attributes(current);
      chunk_.polygon_corners.push_back(current);
    }
    chunk_.polygons.back().corner_count = std::uint32_t(corners);
    return line_end(p);
  }

  [[gnu::noinline]] void note_attributes(const Corner& c) {
    if (c.normal == kNoIndex && chunk_.every_corner_has_normal) {
      chunk_.every_corner_has_normal = false;
      chunk_.triangle_normals = {};
    }
    if (c.texcoord == kNoIndex && chunk_.every_corner_has_texcoord) {
      chunk_.every_corner_has_texcoord = false;
      chunk_.triangle_texcoords = {};
    }
    tracking_attributes_ = chunk_.every_corner_has_normal || chunk_.every_corner_has_texcoord;
  }

  [[gnu::noinline]] void start_polygon(const Corner (&first3)[3]) {
    chunk_.polygons.push_back(
        {std::uint32_t(chunk_.triangles_in_slots), std::uint32_t(chunk_.polygon_corners.size()), 0, seen_.lines});
    chunk_.polygon_corners.insert(chunk_.polygon_corners.end(), first3, first3 + 3);
  }

  void add_triangle(const Corner& a, const Corner& b, const Corner& c) {
    if (a.position == b.position || b.position == c.position || a.position == c.position) {
      ++chunk_.dropped_degenerate;
      return;
    }
    out_.triangles[chunk_.start.faces + chunk_.triangles_in_slots++] =
        TriangleIndices{a.position, b.position, c.position};
    if (chunk_.every_corner_has_normal) chunk_.triangle_normals.push_back({a.normal, b.normal, c.normal});
    if (chunk_.every_corner_has_texcoord) chunk_.triangle_texcoords.push_back({a.texcoord, b.texcoord, c.texcoord});
  }

  // One face vertex: v, v/vt, v//vn or v/vt/vn. Advances p past it.
  [[gnu::always_inline]] Corner corner(const char*& p) {
    std::uint32_t plain = 0;
    if (const int digits = ascii::scan_short_unsigned(p, end_, plain);
        digits > 0 && plain - 1u < out_.totals.positions) {
      p += digits;
      return {plain - 1, kNoIndex, kNoIndex};
    }
    const char* token = p;
    Corner result{index(p, seen_.positions, out_.totals.positions, "vertex"), kNoIndex, kNoIndex};
    if (p != end_ && *p == '/') {
      ++p;
      if (p == end_ || *p != '/')
        result.texcoord = index(p, seen_.texcoords, out_.totals.texcoords, "texture coordinate");
      if (p != end_ && *p == '/') {
        ++p;
        result.normal = index(p, seen_.normals, out_.totals.normals, "normal");
      }
    }
    if (p != end_ && !is_word_end(*p) && *p != '#')
      fail(token, "malformed face vertex " + ascii::quoted(word_at(token, end_)));
    return result;
  }

  // A 1-based index, or a negative one relative to the `declared` elements read so far; returns
  // the 0-based index. Positive indices may point forward, up to the file's total.
  std::uint32_t index(const char*& p, std::uint64_t declared, std::uint64_t total, const char* what) const {
    std::int64_t raw = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(p, end_, raw);
    if (scan.ok && raw > 0 && std::uint64_t(raw) <= total) {
      p = scan.next;
      return std::uint32_t(raw - 1);
    }
    if (scan.ok && raw < 0 && std::uint64_t(-raw) <= declared) {
      p = scan.next;
      return std::uint32_t(declared - std::uint64_t(-raw));
    }
    fail_index(p, scan.ok, raw, declared, total, what);
  }

  [[noreturn, gnu::cold, gnu::noinline]] void fail_index(const char* p, bool is_integer, std::int64_t raw,
                                                         std::uint64_t declared, std::uint64_t total,
                                                         const char* what) const {
    if (!is_integer) fail(p, std::string("expected a ") + what + " index, found " + ascii::quoted(word_at(p, end_)));
    if (raw == 0) fail(p, std::string(what) + " index 0 is invalid: OBJ indices start at 1");
    if (raw > 0)
      fail(p, std::string(what) + " index " + std::to_string(raw) + " is out of range: the file has " +
                  std::to_string(total));
    fail(p, std::string(what) + " index " + std::to_string(raw) + " is out of range: only " + std::to_string(declared) +
                " declared before this line");
  }

  const char* parse_smoothing(const char* p) {
    const std::string_view word = word_at(p, end_);
    std::uint32_t group = kFlat;
    std::int64_t number = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(p, end_, number);
    if (word == "off") {
      group = kFlat;
    } else if (word == "on") {
      group = 1;  // not in the specification, but written by some exporters
    } else if (scan.ok && scan.next == word.data() + word.size() && number >= 0 && std::uint64_t(number) < kInherited) {
      group = std::uint32_t(number);
    } else {
      fail(p, "expected 'off' or a smoothing group number, found " + ascii::quoted(word));
    }
    chunk_.has_smoothing_statement = true;
    change_state().smoothing = group;
    return numbers_then_line_end(skip_word(p, end_), 0, "after the smoothing group");
  }

  const char* parse_usemtl(const char* p) {
    const char* end = ascii::find_line_end(p, end_);
    const std::string_view name = trimmed(p, end);
    // Blender writes a bare `usemtl` for faces without a material: the default material.
    if (name.empty() && chunk_.first_unnamed_usemtl_line == 0) chunk_.first_unnamed_usemtl_line = seen_.lines;
    const auto [slot, inserted] = material_slots_.try_emplace(name, std::uint32_t(chunk_.material_names.size()));
    if (inserted) chunk_.material_names.push_back({name, seen_.lines});
    change_state().material_slot = slot->second;
    return end;
  }

  const char* parse_mtllib(const char* p) {
    if (at_line_end(p)) fail(p, "mtllib needs a file name");
    for (; !at_line_end(p); p = skip_blanks(skip_word(p, end_), end_))
      chunk_.material_libraries.push_back({word_at(p, end_), seen_.lines});
    return line_end(p);
  }

  const char* parse_object_name(const char* p) {
    const char* end = ascii::find_line_end(p, end_);
    if (chunk_.object_name.name.empty()) chunk_.object_name = {trimmed(p, end), seen_.lines};
    return end;
  }

  static std::string_view trimmed(const char* p, const char* end) {
    while (end != p && is_blank(end[-1])) --end;
    return {p, std::size_t(end - p)};
  }

  // The state entry for the next face, carrying over what earlier statements set.
  StateChange& change_state() {
    auto& changes = chunk_.state_changes;
    const auto next_triangle = std::uint32_t(chunk_.triangles_in_slots);
    const auto polygons = std::uint32_t(chunk_.polygons.size());
    if (changes.empty()) {
      changes.push_back({next_triangle, polygons, kInherited, kInherited});
    } else if (changes.back().first_triangle != next_triangle || changes.back().polygons_before != polygons) {
      StateChange carried = changes.back();
      carried.first_triangle = next_triangle;
      carried.polygons_before = polygons;
      changes.push_back(carried);
    }
    return changes.back();
  }

  // A hash lookup, not a scan of the keywords seen so far: a file of 100,000 distinct unknown
  // keywords must not cost 10^10 comparisons.
  void tally_ignored(std::string_view keyword) {
    const auto [slot, inserted] = ignored_slots_.try_emplace(keyword, chunk_.ignored.size());
    if (inserted) chunk_.ignored.push_back({keyword, 1, seen_.lines});
    else ++chunk_.ignored[slot->second].count;
  }

  // A finite float at p; returns the position after it.
  const char* number(const char* p, float& value) const {
    const ascii::FloatScan scan = ascii::scan_real(p, end_, value);
    if (scan.status != ascii::NumberStatus::kOk) fail_number(p, scan.status);
    return scan.next;
  }

  [[noreturn, gnu::cold, gnu::noinline]] void fail_number(const char* p, ascii::NumberStatus status) const {
    if (status == ascii::NumberStatus::kMalformed) fail(p, ascii::quoted(word_at(p, end_)) + " is not a number");
    fail(p, ascii::quoted(word_at(p, end_)) + " is not a finite number in float range");
  }

  // Up to 3 more numbers into `values`; returns how many. p ends after the last one.
  int numbers_into(const char*& p, float (&values)[3], const char* where) const {
    int count = 0;
    for (p = skip_blanks(p, end_); !at_line_end(p); p = skip_blanks(p, end_)) {
      if (count == 3) fail(p, "unexpected " + ascii::quoted(word_at(p, end_)) + " " + where);
      p = number(p, values[count++]);
    }
    return count;
  }

  // Up to `allowed` more numbers (validated, unused), then the end of the line.
  const char* numbers_then_line_end(const char* p, int allowed, const char* where) const {
    for (p = skip_blanks(p, end_); !at_line_end(p); p = skip_blanks(p, end_)) {
      if (allowed-- == 0) fail(p, "unexpected " + ascii::quoted(word_at(p, end_)) + " " + where);
      float unused;
      p = number(p, unused);
    }
    return line_end(p);
  }

  // A statement ends at the end of its line or at a comment.
  bool at_line_end(const char* p) const { return p == end_ || *p == '\n' || *p == '#'; }
  const char* line_end(const char* p) const { return p != end_ && *p == '#' ? ascii::find_line_end(p, end_) : p; }

  [[noreturn, gnu::cold, gnu::noinline]] void fail(const char* at, const std::string& message) const {
    throw InputError(SourceLocation{out_.file, int(seen_.lines), int(at - line_begin_) + 1}, message);
  }

  Chunk& chunk_;
  const Destination& out_;
  Counts seen_;  // everything declared up to the current line, file-wide
  const char* const end_;
  const char* line_begin_ = nullptr;
  std::unordered_map<std::string_view, std::uint32_t> material_slots_;
  std::unordered_map<std::string_view, std::size_t> ignored_slots_;
  bool tracking_attributes_ = true;  // some corner attribute kind is still present on every corner
};

// Counts the line [p, end) as keyword_at() classifies it for the parse. A valid line is at least
// as long as "v 0 0 0", "vn 0 0 0", "vt 0" or "f 1 2 3"; shorter ones are left uncounted.
[[gnu::always_inline]] inline void count_line(const char* p, const char* end, Counts& counts) {
  ++counts.lines;
  const std::ptrdiff_t length = end - p;
  if (length < 4) return;
  if (!is_blank(p[0]) && is_word_end(p[1])) {  // a one-letter keyword: the common case, quickly
    if (p[0] == 'v') counts.positions += length >= 7;
    else if (p[0] == 'f') counts.faces += length >= 7;
    return;
  }
  const std::string_view keyword = keyword_at(p, end);
  if (keyword == "v") counts.positions += length >= 7;
  else if (keyword == "f") counts.faces += length >= 7;
  else if (keyword == "vn") counts.normals += length >= 8;
  else if (keyword == "vt") ++counts.texcoords;
}

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
  const char* line = chunk.text.data();
  const char* const end = line + chunk.text.size();
  ascii::for_each_newline(line, end, [&](const char* newline) {
    count_line(line, newline, counts);
    line = newline + 1;
  });
  if (line != end) count_line(line, end, counts);
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
