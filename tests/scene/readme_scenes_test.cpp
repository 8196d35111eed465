// The README's scene table agrees with the shipped scene files: every file in assets/scenes/ is
// listed exactly once, no row names a scene that is not there, and each row's model column is the
// "model" of every scene it lists.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "io/json.h"

using namespace tidepool;

namespace {

const std::filesystem::path kSource = TIDEPOOL_SOURCE_DIR;

struct Row {
  std::vector<std::string> scenes;  // the first column's `names`
  std::string model;                // the second column
  int line = 0;
};

// The rows of the table headed "| scene | model | what it shows |".
std::vector<Row> readmeSceneTable() {
  std::ifstream in(kSource / "README.md");
  std::vector<Row> rows;
  bool inTable = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("| scene | model |", 0) == 0) {
      inTable = true;
      continue;
    }
    if (!inTable) continue;
    if (line.rfind("|---", 0) == 0) continue;
    if (line.empty() || line[0] != '|') break;
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < line.size(); ++i)
      if (line[i] == '|' && line[i - 1] != '\\') {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += line[i];
      }
    if (cells.size() < 3) {
      ADD_FAILURE() << "README.md:" << number << ": a scene row needs three cells: " << line;
      continue;
    }
    Row row{.line = number};
    const std::regex name("`([^`]+)`");
    for (auto it = std::sregex_iterator(cells[0].begin(), cells[0].end(), name); it != std::sregex_iterator(); ++it)
      row.scenes.push_back((*it)[1]);
    row.model = std::regex_replace(cells[1], std::regex("^ +| +$"), "");
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(ReadmeScenes, TheTableListsEveryShippedSceneOnceWithItsModel) {
  std::map<std::string, std::string> models;  // scene name -> its "model"
  for (const auto& entry : std::filesystem::directory_iterator(kSource / "assets/scenes"))
    if (entry.path().extension() == ".json")
      models[entry.path().stem().string()] = io::readJsonFile(entry.path()).value("model", "");
  ASSERT_GE(models.size(), 30u);

  const std::vector<Row> rows = readmeSceneTable();
  ASSERT_FALSE(rows.empty()) << "no table headed '| scene | model | what it shows |' in README.md";
  std::map<std::string, int> listed;
  for (const Row& row : rows) {
    EXPECT_FALSE(row.scenes.empty()) << "README.md:" << row.line << ": a row without a scene";
    for (const std::string& scene : row.scenes) {
      ++listed[scene];
      const auto it = models.find(scene);
      if (it == models.end()) {
        ADD_FAILURE() << "README.md:" << row.line << ": `" << scene << "` is not a file in assets/scenes/";
        continue;
      }
      EXPECT_EQ(row.model, it->second) << "README.md:" << row.line << ": the model of `" << scene << "`";
    }
  }
  for (const auto& [scene, model] : models)
    EXPECT_EQ(listed[scene], 1) << "`" << scene << "` (" << model << ") listed " << listed[scene]
                                << " times in README.md's scene table";
}
