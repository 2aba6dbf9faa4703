#pragma once
// A YAML document as rtpro's scene reader sees it: a tree of null/scalar/sequence/mapping nodes,
// each knowing where it came from (the scene file or a command-line override). Built from
// libyaml's event stream: a YAML library's own document tree would silently drop duplicate keys
// and could not say which override a node came from. Aliases share the anchored subtree, so `*a`
// costs no memory.
#include "rtpro/core/error.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rtpro {

// Deeper documents are rejected before anything walks them recursively.
inline constexpr int kMaxYamlNesting = 64;
// Longer lines are rejected before parsing: a parser spends seconds on one 100 MB line (most of a
// minute with yaml-cpp, a few seconds with libyaml); no hand-written or generated scene line comes
// near 1 MiB.
inline constexpr std::size_t kMaxYamlLineBytes = std::size_t{1} << 20;

// Refuses lines longer than kMaxYamlLineBytes as text arrives, so a file reader can stop after
// the first long line instead of reading (and paying for) hundreds of MB first.
class LineLengthGuard {
 public:
  explicit LineLengthGuard(std::string source) : source_(std::move(source)) {}
  // The next bytes of the text; throws InputError at the line and the column past the limit.
  void feed(std::string_view bytes);

 private:
  std::string source_;
  int line_ = 1;
  std::size_t current_ = 0;  // bytes of the current line so far
};

// Where a node was written. `source` is owned by the YamlDocument; line/column are 1-based, and 0
// for override values (the override text itself names the place).
struct YamlPosition {
  const std::string* source = nullptr;
  int line = 0;
  int column = 0;

  SourceLocation location() const;
};

struct YamlNode;
// Nodes, their lists and their text live in the arena of the document that made them
// (yaml_node_arena.h), which outlives every view of them; aliases, includes, overrides and
// substituted variables share subtrees by pointing at them.
using YamlNodePtr = const YamlNode*;
struct YamlEntry;
using YamlNodeList = std::span<const YamlNodePtr>;
using YamlEntryList = std::span<const YamlEntry>;

struct YamlEntry {
  std::string_view key;
  YamlPosition key_at;
  YamlNodePtr value = nullptr;
};

// 32 bytes: the scalar's text, the items or the entries, whichever the kind has, are one pointer
// and a size (a large scene is mostly nodes, and their memory is most of its reading time).
struct YamlNode {
  enum class Kind : std::uint8_t { null, scalar, sequence, mapping };

  YamlPosition at;
  Kind kind = Kind::null;
  bool plain = true;  // an unquoted scalar: only plain scalars are numbers

  bool is_null() const { return kind == Kind::null; }
  bool is_scalar() const { return kind == Kind::scalar; }
  bool is_sequence() const { return kind == Kind::sequence; }
  bool is_mapping() const { return kind == Kind::mapping; }
  // Empty for a node of another kind.
  std::string_view scalar() const {
    return is_scalar() ? std::string_view(static_cast<const char*>(data_), size_) : std::string_view();
  }
  YamlNodeList items() const {
    return is_sequence() ? YamlNodeList(static_cast<const YamlNodePtr*>(data_), size_) : YamlNodeList();
  }
  // In document order, keys unique.
  YamlEntryList entries() const {
    return is_mapping() ? YamlEntryList(static_cast<const YamlEntry*>(data_), size_) : YamlEntryList();
  }
  void set_scalar(std::string_view text) { set(text.data(), text.size()); }
  void set_items(YamlNodeList list) { set(list.data(), list.size()); }
  void set_entries(YamlEntryList list) { set(list.data(), list.size()); }

  const YamlEntry* find(std::string_view key) const;
  // "a number", "a list of 2 items", ... for "expected X, got Y" messages.
  std::string describe() const;

 private:
  // Sizes fit: a line is at most kMaxYamlLineBytes, and a list of 2^32 items would take 32 GB.
  void set(const void* data, std::size_t size) {
    data_ = data;
    size_ = static_cast<std::uint32_t>(size);
  }

  std::uint32_t size_ = 0;
  const void* data_ = nullptr;
};

class YamlNodeArena;

// Reads the text of an included file with the same checks as the scene file itself.
using YamlFileReader = std::function<std::string(const std::filesystem::path&)>;
// Deeper chains of includes are refused (a chain that long is a mistake, or a cycle in disguise).
inline constexpr int kMaxIncludeDepth = 16;
// Includes read while one scene is parsed, counting a file each time it is included, and the
// bytes they hold together: a file that includes another twice, 16 levels deep, reads 65,536
// files (gigabytes from a few small ones) without ever nesting too deep.
inline constexpr std::size_t kMaxIncludesRead = 1024;
inline constexpr std::uint64_t kMaxIncludedBytes = std::uint64_t{256} << 20;

// The includes being expanded: the chain from the scene file to the current file, and the
// totals over the whole scene.
struct IncludeWalk {
  std::vector<std::filesystem::path> chain;
  std::size_t files_read = 0;
  std::uint64_t bytes_read = 0;
};

// The path that identifies a file in an include chain (symbolic links and `..` resolved).
std::filesystem::path include_identity(const std::filesystem::path& file);

class YamlDocument {
 public:
  // Throws InputError at the offending position for syntax errors, duplicate keys, non-scalar
  // keys, explicit tags, nesting deeper than kMaxYamlNesting, lines longer than
  // kMaxYamlLineBytes, and more than one document. An empty text gives a null root.
  //
  // With `read_include`, `include: FILE` (or a list of files) is expanded, FILE relative to the
  // file that names it (yaml_include.cpp): in a mapping, the included mapping's keys are merged
  // in, the including mapping's own keys winning; a list item that is only `{include: FILE}` is
  // replaced by the file's items (a list) or by the file's mapping. Cycles and chains deeper than
  // kMaxIncludeDepth are refused at the include, so is the include past kMaxIncludesRead files
  // or kMaxIncludedBytes in all; errors inside an included file name that file.
  static YamlDocument parse(std::string_view text, const std::string& source_name,
                            const YamlFileReader& read_include = {});

  YamlDocument(YamlDocument&&) = default;
  YamlDocument& operator=(YamlDocument&&) = default;
  YamlDocument(const YamlDocument&) = delete;  // positions point into sources_
  YamlDocument& operator=(const YamlDocument&) = delete;

  // Applies "dotted.key=value" (the value is YAML): sets that key, creating missing mappings on
  // the way; a numeric segment indexes into an existing list. The new nodes are positioned at the
  // override, so later errors about them name it.
  void apply_override(const std::string& override_text);

  // Removes the root's `variables:` mapping (defaults, which -D overrides as variables.NAME) and
  // substitutes its values (yaml_variables.cpp): a scalar that is just `$name` or `${name}` becomes
  // the variable's value (a number, a list, a mapping); inside longer text `${name}` or `$name`
  // is replaced by a scalar variable's text; `$$` is a literal `$`. An undefined name is an
  // error at its use, with the nearest defined name suggested. Call after the overrides.
  void resolve_variables();

  const YamlNode& root() const { return *root_; }

  // The frame keyframes were read at (the scene variable `frame`; 1 when unset).
  double frame() const { return frame_; }
  // A node of root() as it reads at another frame: its keyframes and $frame substituted again
  // (a motion blur's time steps read a keyframed transform this way). The node itself where no
  // substitution touched it.
  YamlNodePtr at_frame(const YamlNode& resolved, double frame) const;

 private:
  YamlDocument() = default;
  static YamlDocument parse_included(std::string_view text, const std::string& source_name,
                                     const YamlFileReader& read_include, IncludeWalk& walk);
  YamlNodePtr expand_includes(YamlNodePtr node, const YamlFileReader& read_include, IncludeWalk& walk);
  YamlNodePtr load_include(const YamlNode& file_name, const YamlFileReader& read_include, IncludeWalk& walk);

  std::deque<std::string> sources_;                      // stable addresses for YamlPosition::source
  std::vector<std::unique_ptr<YamlDocument>> includes_;  // keep the included files' sources and nodes
  std::shared_ptr<YamlNodeArena> arena_;                 // this document's nodes, its overrides' and substitutions'
  YamlNodePtr root_ = nullptr;
  bool has_includes_ = false;   // an `include` key was read: expansion walks the tree
  bool has_variables_ = false;  // a `$`, `variables` or `keyframes` was read: substitution walks it
  // Kept by resolve_variables for at_frame: the variables and each substituted node's original.
  YamlNodePtr variables_ = nullptr;
  std::unordered_map<const YamlNode*, YamlNodePtr> originals_;
  double frame_ = 1.0;
};

}  // namespace rtpro
