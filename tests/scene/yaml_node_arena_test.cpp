// The arena that holds a YAML document's nodes, lists and text: copies that do not depend on
// what they were made from, and that stay put while the arena grows block after block.
#include "yaml_node_arena.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro {
namespace {

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

}  // namespace
}  // namespace rtpro
