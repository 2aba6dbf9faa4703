// The arena that holds a YAML document's nodes, lists and text: copies that do not depend on
// what they were made from, and that stay put while the arena grows block after block.
#include "yaml_node_arena.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro {
namespace yaml_node_arena_test {

TEST(YamlNodeArena, TextAndListsAreCopiesThatOutliveTheirSources) {
  YamlNodeArena arena;
  std::string_view text;
  YamlNodeList items;
  YamlEntryList entries;
  YamlNode* first = arena.node();
  YamlNode* second = arena.node();
  {
    std::string source = "center";
    text = arena.text(source);
    source.assign("XXXXXX");
    std::vector<YamlNodePtr> item_source{first, second, first};
    items = arena.list(item_source);
    item_source.assign(3, nullptr);
    std::vector<YamlEntry> entry_source{{text, {}, first}, {text, {}, second}};
    entries = arena.list(entry_source);
    entry_source.clear();
  }
  EXPECT_EQ(text, "center");
  ASSERT_EQ(items.size(), 3u);
  EXPECT_EQ(items[0], first);
  EXPECT_EQ(items[1], second);
  EXPECT_EQ(items[2], first);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].key, "center");
  EXPECT_EQ(entries[1].value, second);
}

// A changed list or mapping: a new node with the old one's kind and position, its children shared.
TEST(YamlNodeArena, WithItemsAndWithEntriesCopyTheNodeAndShareTheChildren) {
  YamlNodeArena arena;
  YamlNode* child = arena.node();
  YamlNode list;
  list.kind = YamlNode::Kind::sequence;
  list.at.line = 7;
  const std::vector<YamlNodePtr> items{child, child};
  const YamlNodePtr changed = arena.with_items(list, items);
  EXPECT_NE(changed, &list);
  EXPECT_TRUE(changed->is_sequence());
  EXPECT_EQ(changed->at.line, 7);
  ASSERT_EQ(changed->items().size(), 2u);
  EXPECT_EQ(changed->items()[1], child);
  EXPECT_TRUE(list.items().empty());

  YamlNode mapping;
  mapping.kind = YamlNode::Kind::mapping;
  const std::vector<YamlEntry> entries{{arena.text("key"), {}, child}};
  const YamlNodePtr with_key = arena.with_entries(mapping, entries);
  EXPECT_TRUE(with_key->is_mapping());
  ASSERT_NE(with_key->find("key"), nullptr);
  EXPECT_EQ(with_key->find("key")->value, child);
  EXPECT_TRUE(mapping.entries().empty());
}

TEST(YamlNodeArena, EmptyCopiesAreEmpty) {
  YamlNodeArena arena;
  EXPECT_TRUE(arena.text("").empty());
  EXPECT_TRUE(arena.list(std::vector<YamlNodePtr>{}).empty());
  EXPECT_TRUE(arena.list(std::vector<YamlEntry>{}).empty());
}

// Far more than the first block: what was given out before each new block keeps its contents.
TEST(YamlNodeArena, EarlierNodesAndTextSurviveManyBlocks) {
  YamlNodeArena arena;
  std::vector<YamlNode*> nodes;
  std::vector<std::string_view> texts;
  for (int i = 0; i < 200000; ++i) {
    YamlNode* node = arena.node();
    node->kind = YamlNode::Kind::scalar;
    node->at.line = i + 1;
    texts.push_back(arena.text(std::to_string(i)));
    node->set_scalar(texts.back());
    nodes.push_back(node);
  }
  for (int i = 0; i < 200000; i += 997) {
    EXPECT_EQ(nodes[i]->at.line, i + 1);
    EXPECT_EQ(nodes[i]->scalar(), std::to_string(i));
  }
}

}  // namespace yaml_node_arena_test
}  // namespace rtpro
