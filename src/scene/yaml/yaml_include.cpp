// `include:` in YAML scenes: shared materials, lights or a base scene kept in files of their own.
#include "yaml_document.h"

#include "yaml_node_arena.h"

#include <algorithm>

namespace rtpro {

namespace {

bool is_include_only(const YamlNode& node) {
  return node.is_mapping() && node.entries().size() == 1 && node.entries()[0].key == "include";
}

// The file names of an `include:` value: one name or a list of names.
std::vector<const YamlNode*> include_names(const YamlNode& value) {
  if (value.is_scalar()) return {&value};
  if (value.is_sequence() && !value.items().empty()) {
    std::vector<const YamlNode*> names;
    for (const YamlNodePtr& item : value.items()) {
      if (!item->is_scalar())
        throw InputError(item->at.location(), "include: expected a file name, got " + item->describe());
      names.push_back(item);
    }
    return names;
  }
  throw InputError(value.at.location(),
                   "include: expected a file name or a list of file names, got " + value.describe());
}

std::string chain_text(const std::vector<std::filesystem::path>& chain, const std::filesystem::path& last) {
  std::string text;
  for (const auto& file : chain) text += file.filename().string() + " -> ";
  return text + last.filename().string();
}

// `entries` with `added` merged in: an added key replaces an existing one in place.
void merge_entries(std::vector<YamlEntry>& entries, YamlEntryList added) {
  for (const YamlEntry& entry : added) {
    const auto same =
        std::find_if(entries.begin(), entries.end(), [&](const YamlEntry& e) { return e.key == entry.key; });
    if (same == entries.end()) {
      entries.push_back(entry);
    } else {
      *same = entry;
    }
  }
}

}  // namespace

YamlNodePtr YamlDocument::load_include(const YamlNode& file_name, const YamlFileReader& read_include,
                                       IncludeWalk& walk) {
  const std::vector<std::filesystem::path>& chain = walk.chain;
  const SourceLocation where = file_name.at.location();
  if (file_name.scalar().empty()) throw InputError(where, "include: the file name is empty");
  const std::filesystem::path base =
      file_name.at.source ? std::filesystem::path(*file_name.at.source).parent_path() : std::filesystem::path();
  const std::filesystem::path file = base / std::filesystem::path(file_name.scalar());
  const std::filesystem::path identity = include_identity(file);
  if (std::find(chain.begin(), chain.end(), identity) != chain.end())
    throw InputError(where, "include cycle: " + chain_text(chain, identity));
  if (chain.size() >= static_cast<std::size_t>(kMaxIncludeDepth))
    throw InputError(where, "includes nested deeper than " + std::to_string(kMaxIncludeDepth) +
                                " files: " + chain_text(chain, identity));
  if (++walk.files_read > kMaxIncludesRead)
    throw InputError(
        where, "more than " + std::to_string(kMaxIncludesRead) +
                   " includes in one scene (each counted every time it is included; the limit on included files)");
  std::string text;
  try {
    text = read_include(file);
  } catch (const InputError& e) {
    throw InputError(
        where, "cannot include '" + std::string(file_name.scalar()) + "' (" + file.string() + "): " + e.message());
  }
  walk.bytes_read += text.size();
  if (walk.bytes_read > kMaxIncludedBytes)
    throw InputError(where, "the included files hold more than " + std::to_string(kMaxIncludedBytes >> 20) +
                                " MiB together (each counted every time it is included; the limit on included text)");
  auto included = std::make_unique<YamlDocument>(parse_included(text, file.string(), read_include, walk));
  YamlNodePtr root = included->root_;
  has_variables_ = has_variables_ || included->has_variables_;
  includes_.push_back(std::move(included));
  return root;
}

YamlNodePtr YamlDocument::expand_includes(YamlNodePtr node, const YamlFileReader& read_include, IncludeWalk& walk) {
  if (node->is_sequence()) {
    std::vector<YamlNodePtr> items;
    for (const YamlNodePtr& item : node->items()) {
      if (!is_include_only(*item)) {
        items.push_back(expand_includes(item, read_include, walk));
        continue;
      }
      for (const YamlNode* name : include_names(*item->entries()[0].value)) {
        const YamlNodePtr included = load_include(*name, read_include, walk);
        if (included->is_sequence()) {
          items.insert(items.end(), included->items().begin(), included->items().end());
        } else if (included->is_mapping()) {
          items.push_back(included);
        } else if (!included->is_null()) {
          throw InputError(name->at.location(), "include '" + std::string(name->scalar()) +
                                                    "': a list item includes a list or a mapping, got " +
                                                    included->describe());
        }
      }
    }
    return arena_->with_items(*node, items);
  }
  if (!node->is_mapping()) return node;
  std::vector<YamlEntry> entries;
  const YamlEntry* include = node->find("include");
  if (include) {
    for (const YamlNode* name : include_names(*include->value)) {
      const YamlNodePtr included = load_include(*name, read_include, walk);
      if (included->is_null()) continue;
      if (!included->is_mapping())
        throw InputError(name->at.location(), "include '" + std::string(name->scalar()) +
                                                  "': a mapping includes a mapping, got " + included->describe());
      merge_entries(entries, included->entries());
    }
  }
  std::vector<YamlEntry> own;
  for (const YamlEntry& entry : node->entries())
    if (&entry != include) own.push_back({entry.key, entry.key_at, expand_includes(entry.value, read_include, walk)});
  merge_entries(entries, own);
  return arena_->with_entries(*node, entries);
}

}  // namespace rtpro
