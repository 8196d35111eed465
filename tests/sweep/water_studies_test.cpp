// The water studies of issue 18: rows of several models in one CSV.
#include <gtest/gtest.h>

#include <fstream>

#include "support/gl_test.h"
#include "sweep/sweep.h"

using namespace tidepool;

namespace {

std::string text(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

// A study of several models writes each row's model; a row without one takes the result's, and
// reads back without one.
TEST(WaterStudies, RowModelsRoundTripThroughTheCsv) {
  test::TempDir dir;
  sweep::Result r = sweep::emptyResult("water", {"error"});
  for (const char* model : {"balls", "fluid", ""}) {
    sweep::Row row;
    row.model = model;
    row.method = "m, 1";
    row.metrics = {0.5};
    r.rows.push_back(row);
  }
  sweep::writeCsv(r, "s", "dev", dir / "s.csv");
  sweep::writeChartSpec(r, dir / "s.chart.json");
  const std::string csv = text(dir / "s.csv");
  EXPECT_NE(csv.find("\ns,balls,\"m, 1\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ns,fluid,\"m, 1\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ns,water,\"m, 1\","), std::string::npos) << csv;
  std::string device;
  const sweep::Result back = sweep::readResult(dir / "s.csv", dir / "s.chart.json", device);
  ASSERT_EQ(back.rows.size(), 3u);
  EXPECT_EQ(back.model, "water");
  EXPECT_EQ(back.rows[0].model, "balls");
  EXPECT_EQ(back.rows[1].model, "fluid");
  EXPECT_EQ(back.rows[2].model, "") << "the result's own model reads back as none of the row's";
  EXPECT_EQ(device, "dev");
}
