// The feature audit of tests/README.md: its table has one row per type the loader accepts
// (scene_types.cpp), no empty cell, goldens that exist and draw the row's type, and tests
// that are defined in tests/LABEL/*.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "golden/golden_manifest.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

struct AuditRow {
  std::string category, type;
  std::vector<std::string> goldens, tests;
};

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> backticked(const std::string& cell) {
  std::vector<std::string> names;
  const std::regex name("`([^`]+)`");
  for (auto it = std::sregex_iterator(cell.begin(), cell.end(), name); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// The rows of the table under "## Feature audit", past its header and separator.
std::vector<AuditRow> audit_table() {
  std::istringstream in(read_file(test::source_path("tests/README.md")));
  std::string line;
  while (std::getline(in, line) && line != "## Feature audit") {
  }
  std::vector<AuditRow> rows;
  int table_lines = 0;
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (table_lines > 0) break;
      continue;
    }
    if (++table_lines <= 2) continue;  // header and --- separator
    std::vector<std::string> cells;
    std::stringstream s(line.substr(1));
    std::string cell;
    while (std::getline(s, cell, '|')) cells.push_back(cell);
    EXPECT_EQ(cells.size(), 4u) << line;
    if (cells.size() != 4) continue;
    rows.push_back({trim(cells[0]), trim(cells[1]), backticked(cells[2]), backticked(cells[3])});
  }
  return rows;
}

// "Suite.Name" of every TEST, TEST_F and TEST_P in tests/LABEL/*.cpp.
std::set<std::string> defined_tests() {
  std::set<std::string> names;
  const std::regex test(R"(\bTEST(?:_F|_P)?\((\w+),\s*(\w+)\))");
  for (const auto& f : std::filesystem::recursive_directory_iterator(test::source_path("tests"))) {
    if (f.path().extension() != ".cpp") continue;
    const std::string text = read_file(f.path().string());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), test); it != std::sregex_iterator(); ++it)
      names.insert((*it)[1].str() + "." + (*it)[2].str());
  }
  return names;
}

TEST(FeatureAudit, TableRowsAreTheLoadersTypes) {
  std::set<std::string> listed, accepted;
  for (const AuditRow& row : audit_table()) {
    EXPECT_TRUE(listed.insert(row.category + ":" + row.type).second)
        << "listed twice: " << row.category << " " << row.type;
  }
  for (const auto& [category, names] : accepted_scene_types())
    for (const std::string& name : names) accepted.insert(category + ":" + name);
  for (const std::string& t : accepted)
    EXPECT_TRUE(listed.count(t)) << "the loader accepts " << t << "; tests/README.md has no row for it";
  for (const std::string& t : listed)
    EXPECT_TRUE(accepted.count(t)) << "tests/README.md lists " << t << ", which the loader does not accept";
  EXPECT_GE(listed.size(), 39u);
}

TEST(FeatureAudit, EveryGoldenExistsAndDrawsItsType) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  std::map<std::string, std::set<std::string>> drawn;  // golden -> the types its scene uses
  for (const AuditRow& row : audit_table()) {
    EXPECT_FALSE(row.goldens.empty()) << row.category << " " << row.type << " has no golden";
    for (const std::string& name : row.goldens) {
      if (!drawn.count(name)) {
        const auto it = std::find_if(manifest.entries.begin(), manifest.entries.end(),
                                     [&](const GoldenEntry& e) { return e.name == name; });
        if (it == manifest.entries.end()) {
          ADD_FAILURE() << row.category << " " << row.type << ": golden " << name << " is not in golden/manifest.json";
          continue;
        }
        drawn[name] = load_scene(manifest.scene_path(*it), RenderOverrides{it->options}).report.used_types;
      }
      EXPECT_TRUE(drawn[name].count(row.category + ":" + row.type))
          << "golden " << name << " does not draw " << row.category << " " << row.type;
    }
  }
}

TEST(FeatureAudit, EveryClosedFormTestIsDefined) {
  const std::set<std::string> tests = defined_tests();
  ASSERT_GT(tests.size(), 100u);
  for (const AuditRow& row : audit_table()) {
    EXPECT_FALSE(row.tests.empty()) << row.category << " " << row.type << " has no closed-form test";
    for (const std::string& name : row.tests)
      EXPECT_TRUE(tests.count(name)) << row.category << " " << row.type << ": no test " << name;
  }
}

}  // namespace
}  // namespace tracer
