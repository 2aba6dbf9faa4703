// YamlDocument at the level of its nodes: what each kind of node answers, which nodes are shared
// rather than copied, and that everything a document hands out lives as long as the document,
// whatever happened to the text, the included files' text and the overrides it was made from.
#include "yaml_document.h"

#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

namespace rtpro {
namespace yaml_document_test {

const YamlNode& value_of(const YamlNode& mapping, std::string_view key) {
  const YamlEntry* entry = mapping.find(key);
  if (!entry) throw std::runtime_error("no key " + std::string(key));
  return *entry->value;
}

TEST(YamlDocument, EachKindAnswersOnlyForItselfAndKeepsItsPosition) {
  const YamlDocument document = YamlDocument::parse("a: 1.5\nb: [x, 'y']\nc: {d: e}\nf:\n", "scene.yaml");
  const YamlNode& root = document.root();
  ASSERT_TRUE(root.is_mapping());
  ASSERT_EQ(root.entries().size(), 4u);
  EXPECT_TRUE(root.items().empty());
  EXPECT_TRUE(root.scalar().empty());

  const YamlNode& a = value_of(root, "a");
  EXPECT_TRUE(a.is_scalar());
  EXPECT_EQ(a.scalar(), "1.5");
  EXPECT_TRUE(a.plain);
  EXPECT_TRUE(a.items().empty());
  EXPECT_TRUE(a.entries().empty());
  EXPECT_EQ(a.at.line, 1);
  EXPECT_EQ(a.at.column, 4);
  EXPECT_EQ(*a.at.source, "scene.yaml");

  const YamlNode& b = value_of(root, "b");
  ASSERT_EQ(b.items().size(), 2u);
  EXPECT_TRUE(b.scalar().empty());
  EXPECT_TRUE(b.entries().empty());
  EXPECT_EQ(b.items()[1]->scalar(), "y");
  EXPECT_FALSE(b.items()[1]->plain);
  EXPECT_EQ(b.describe(), "a list of 2 items");

  EXPECT_EQ(value_of(value_of(root, "c"), "d").scalar(), "e");
  // An empty value is a null node placed at its key.
  const YamlNode& f = value_of(root, "f");
  EXPECT_TRUE(f.is_null());
  EXPECT_TRUE(f.scalar().empty() && f.items().empty() && f.entries().empty());
  EXPECT_EQ(f.at.line, 4);
  EXPECT_EQ(f.at.column, 1);
}

TEST(YamlDocument, OutlivesTheTextItWasParsedFrom) {
  auto text = std::make_unique<std::string>("name: a_long_enough_value_to_live_on_the_heap\nlist: [1, 2, 3]\n");
  const YamlDocument document = YamlDocument::parse(*text, "scene.yaml");
  text->assign(text->size(), '#');
  text.reset();
  EXPECT_EQ(value_of(document.root(), "name").scalar(), "a_long_enough_value_to_live_on_the_heap");
  EXPECT_EQ(value_of(document.root(), "list").items()[2]->scalar(), "3");
  EXPECT_EQ(document.root().entries()[1].key, "list");
}

TEST(YamlDocument, AliasesAreTheAnchoredNodeItself) {
  const YamlDocument document =
      YamlDocument::parse("a: &shared {x: [1, 2]}\nb: *shared\nc: [*shared, *shared]\n", "s.yaml");
  const YamlNode& root = document.root();
  const YamlNode* anchored = &value_of(root, "a");
  EXPECT_EQ(&value_of(root, "b"), anchored);
  EXPECT_EQ(value_of(root, "c").items()[0], anchored);
  EXPECT_EQ(value_of(root, "c").items()[1], anchored);
}

TEST(YamlDocument, OverridesCopyThePathAndLeaveSharedNodesAlone) {
  YamlDocument document = YamlDocument::parse("a: &shared {x: 1, y: 2}\nb: *shared\n", "s.yaml");
  const YamlNode* before = &document.root();
  const YamlNode* shared = &value_of(*before, "a");
  document.apply_override("b.x=7");
  const YamlNode& root = document.root();
  EXPECT_EQ(&value_of(root, "a"), shared);
  EXPECT_EQ(value_of(value_of(root, "a"), "x").scalar(), "1");
  const YamlNode& b = value_of(root, "b");
  EXPECT_NE(&b, shared);
  EXPECT_EQ(value_of(b, "x").scalar(), "7");
  EXPECT_EQ(value_of(b, "x").at.line, 0);  // placed at the override
  EXPECT_EQ(&value_of(b, "y"), &value_of(*shared, "y"));
  // The tree from before the override is still whole: nothing was changed in place.
  EXPECT_EQ(value_of(value_of(*before, "b"), "x").scalar(), "1");
}

TEST(YamlDocument, OverrideValuesOutliveTheOverrideText) {
  YamlDocument document = YamlDocument::parse("render: {spp: 4}\n", "s.yaml");
  {
    auto text = std::make_unique<std::string>("render.list=[first_item_with_a_long_name, second]");
    document.apply_override(*text);
    text->assign(text->size(), '#');
  }
  const YamlNode& list = value_of(value_of(document.root(), "render"), "list");
  ASSERT_EQ(list.items().size(), 2u);
  EXPECT_EQ(list.items()[0]->scalar(), "first_item_with_a_long_name");
  EXPECT_EQ(value_of(value_of(document.root(), "render"), "spp").scalar(), "4");
}

TEST(YamlDocument, IncludedNodesOutliveTheIncludedText) {
  const auto read = [](const std::filesystem::path& file) {
    if (file.filename() == "materials.yaml")
      return std::string("red: {color: [1, 0, 0]}\nname: from_the_included_file\n");
    throw InputError(SourceLocation{file.string()}, "no such file");
  };
  const YamlDocument document = YamlDocument::parse("materials: {include: materials.yaml, blue: {color: [0, 0, 1]}}\n",
                                                    "/scenes/scene.yaml", read);
  const YamlNode& materials = value_of(document.root(), "materials");
  ASSERT_EQ(materials.entries().size(), 3u);
  EXPECT_EQ(materials.entries()[0].key, "red");
  EXPECT_EQ(materials.entries()[2].key, "blue");
  const YamlNode& name = value_of(materials, "name");
  EXPECT_EQ(name.scalar(), "from_the_included_file");
  EXPECT_EQ(std::filesystem::path(*name.at.source).filename(), "materials.yaml");
  EXPECT_EQ(name.at.line, 2);
}

TEST(YamlDocument, VariablesAreSubstitutedIntoNewNodesAndRemoved) {
  YamlDocument document =
      YamlDocument::parse("variables: {n: 16, who: world}\nspp: $n\ngreeting: hello ${who}\n", "s.yaml");
  document.apply_override("variables.who=everyone");
  document.resolve_variables();
  const YamlNode& root = document.root();
  EXPECT_EQ(root.find("variables"), nullptr);
  EXPECT_EQ(value_of(root, "spp").scalar(), "16");
  EXPECT_EQ(value_of(root, "greeting").scalar(), "hello everyone");
  EXPECT_EQ(value_of(root, "greeting").at.line, 3);
}

}  // namespace yaml_document_test
}  // namespace rtpro
