// The scene file's schema (Tool/vsSceneSchema.h) against its documentation and its
// parser: docs/reference.md ("The scene file") lists exactly the table's keys (and each Word
// key's words), and a key set to the table's default parses as the key left out.
#include "vsSceneFile.h"
#include "vsSceneSchema.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using json = nlohmann::json;
using vstool::SceneKey;
using vstool::SceneSchema;
using vstool::SceneType;

namespace
{
// docs/reference.md's section "## The scene file": the keys it documents.
struct Reference
{
  std::set<std::string> ExampleKeys;                         // "key": in the example before the first ###
  std::set<std::string> Sections;                            // ### `section`
  std::map<std::string, std::set<std::string>> TableKeys;    // section -> `key` in its tables' first column
  std::map<std::string, std::set<std::string>> QuotedKeys;   // section -> "key": in its text (nested keys)
  std::map<std::string, std::map<std::string, std::string>> Rows; // section -> key -> its table row
  std::map<std::string, std::string> Text;                   // section -> its text
};

Reference ReadReference()
{
  std::ifstream in(VISSWEEP_REFERENCE_MD);
  EXPECT_TRUE(in) << VISSWEEP_REFERENCE_MD;
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const size_t begin = all.find("\n## The scene file");
  EXPECT_NE(begin, std::string::npos);
  const size_t end = all.find("\n## ", begin + 1);
  std::istringstream lines(all.substr(begin, end == std::string::npos ? std::string::npos : end - begin));

  const std::regex heading("^### `(\\w+)`.*");
  const std::regex backticked("`(\\w+)`");
  const std::regex quoted("\"(\\w+)\":");
  Reference r;
  std::string section; // "" before the first ###
  std::string line;
  while (std::getline(lines, line))
  {
    std::smatch m;
    if (std::regex_match(line, m, heading))
    {
      section = m[1];
      r.Sections.insert(section);
      continue;
    }
    if (!section.empty())
    {
      r.Text[section] += line + "\n";
    }
    for (auto it = std::sregex_iterator(line.begin(), line.end(), quoted); it != std::sregex_iterator(); ++it)
    {
      (section.empty() ? r.ExampleKeys : r.QuotedKeys[section]).insert((*it)[1]);
    }
    if (!section.empty() && line.rfind("| `", 0) == 0)
    {
      const std::string first = line.substr(1, line.find('|', 1) - 1);
      for (auto it = std::sregex_iterator(first.begin(), first.end(), backticked); it != std::sregex_iterator(); ++it)
      {
        r.TableKeys[section].insert((*it)[1]);
        r.Rows[section][(*it)[1]] = line;
      }
    }
  }
  return r;
}

// "environment.sun" -> "environment", "clip_planes[]" -> "clip_planes".
std::string TopSection(const std::string& section)
{
  return section.substr(0, section.find_first_of(".["));
}
}

TEST(SceneFile, ReferenceDocumentsEverySchemaKey)
{
  const Reference r = ReadReference();
  for (const SceneKey& k : SceneSchema())
  {
    SCOPED_TRACE(k.Path());
    const std::string section = k.Section;
    if (section.empty()) // a top-level key: its own ### section, or in the example
    {
      EXPECT_TRUE(r.Sections.count(k.Key) || r.ExampleKeys.count(k.Key)) << "not in docs/reference.md";
    }
    else if (section == TopSection(section)) // a section's key: a row of its table
    {
      EXPECT_TRUE(r.TableKeys.count(section) && r.TableKeys.at(section).count(k.Key))
        << "no row of `" << k.Key << "` under ### `" << section << "` in docs/reference.md";
    }
    else // a nested key ("environment.sun"): quoted in its section's text
    {
      const std::string top = TopSection(section);
      EXPECT_TRUE(r.QuotedKeys.count(top) && r.QuotedKeys.at(top).count(k.Key))
        << "no \"" << k.Key << "\": under ### `" << top << "` in docs/reference.md";
    }
  }
}

TEST(SceneFile, SchemaHasEveryReferenceKey)
{
  const Reference r = ReadReference();
  auto inSchema = [](const std::function<bool(const SceneKey&)>& match) {
    for (const SceneKey& k : SceneSchema())
    {
      if (match(k))
      {
        return true;
      }
    }
    return false;
  };
  for (const std::string& s : r.Sections)
  {
    EXPECT_TRUE(inSchema([&](const SceneKey& k) { return !*k.Section && s == k.Key; }))
      << "### `" << s << "` of docs/reference.md is no top-level key of the schema";
  }
  for (const std::string& key : r.ExampleKeys)
  {
    EXPECT_TRUE(inSchema([&](const SceneKey& k) { return key == k.Key; }))
      << "the example of docs/reference.md has \"" << key << "\", which the schema lacks";
  }
  for (const auto& [section, keys] : r.TableKeys)
  {
    for (const std::string& key : keys)
    {
      EXPECT_TRUE(inSchema([&](const SceneKey& k) { return section == k.Section && key == k.Key; }))
        << "docs/reference.md documents `" << section << "." << key << "`, which the schema lacks";
    }
  }
  for (const auto& [section, keys] : r.QuotedKeys)
  {
    for (const std::string& key : keys)
    {
      EXPECT_TRUE(inSchema([&](const SceneKey& k) { return TopSection(k.Section) == section && key == k.Key; }))
        << "docs/reference.md quotes \"" << key << "\": under ### `" << section << "`, which the schema lacks";
    }
  }
}

TEST(SceneFile, ReferenceNamesEveryWord)
{
  const Reference r = ReadReference();
  for (const SceneKey& k : SceneSchema())
  {
    if (k.Type != SceneType::Word)
    {
      continue;
    }
    SCOPED_TRACE(k.Path());
    const std::string top = TopSection(k.Section);
    if (top != k.Section) // a nested key ("lights[].type"): its words in its section's text
    {
      ASSERT_TRUE(r.Text.count(top));
      for (const std::string& word : k.Words)
      {
        EXPECT_NE(r.Text.at(top).find("`" + word + "`"), std::string::npos) << "### `" << top << "` does not name `"
                                                                           << word << "`";
      }
      continue;
    }
    ASSERT_TRUE(r.Rows.count(k.Section) && r.Rows.at(k.Section).count(k.Key));
    const std::string& row = r.Rows.at(k.Section).at(k.Key);
    for (const std::string& word : k.Words)
    {
      EXPECT_NE(row.find("`" + word + "`"), std::string::npos) << "its row does not name `" << word << "`";
    }
  }
}

// Each default of the table is the parser's: a scene with the key set to it equals the scene
// without the key.
TEST(SceneFile, SchemaDefaultsAreTheParsers)
{
  const json base = json::parse(R"({
    "volume": {"files": ["a.vdb", "b.vdb"]},
    "transfer_function": {"opacity": [[0, 0], [1, 1]]},
    "environment": {"file": "sky.exr"},
    "camera": {"position": [0, -5, 0], "focal_point": [0, 0, 0]},
    "render": {}
  })");
  int checked = 0;
  for (const SceneKey& k : SceneSchema())
  {
    if (!k.Default)
    {
      continue;
    }
    SCOPED_TRACE(k.Path());
    json without = base;
    if (std::string(k.Section) == "environment.sun")
    {
      without["environment"] = json::parse(R"({"sun": {"direction": [0, 0, 1]}})");
    }
    const bool light = std::string(k.Section) == "lights[]";
    if (light)
    {
      // A spot light takes every key of a light (its cone, exponent and attenuation); the type's own
      // default is checked on a light without a type.
      without["lights"] = json::array({ std::string(k.Key) == "type" ? json::object() : json{ { "type", "spot" } } });
    }
    json with = without;
    json* section = &with;
    std::istringstream parts(light ? std::string() : std::string(k.Section));
    for (std::string part; std::getline(parts, part, '.');)
    {
      section = &(*section)[part];
    }
    if (light)
    {
      section = &with["lights"][0];
    }
    (*section)[k.Key] = json::parse(k.Default);
    EXPECT_TRUE(vstool::ParseScene(with, "/x") == vstool::ParseScene(without, "/x")) << with.dump();
    ++checked;
  }
  EXPECT_GE(checked, 20);
}
