// "method": "auto": the selection rule on synthetic rows, the shipped data, and the one-line
// errors for what a scene can state wrongly. Real runs of the picks: tests/sim/auto_real_run_test.cpp;
// "model": "auto": water_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "scene/auto/candidates.h"
#include "scene/param_json.h"
#include "scene/scene.h"
#include "sim/balls/balls_params.h"
#include "sim/ripples/ripples_params.h"
#include "sim/swarm/swarm_params.h"
#include "support/gl_test.h"
#include "support/run_process.h"
#include "support/scene_error.h"
#include "sweep/sweep.h"

using namespace tidepool;
using namespace tidepool::automethod;
using test::sceneError;

namespace {

Candidate row(const std::string& family, double step, double cost, double error, bool stable = true) {
  Candidate c;
  c.label = family + " at " + std::to_string(step);
  c.family = family;
  c.step = step;
  c.cost = cost;
  c.errors = {error};
  c.stable = stable;
  return c;
}

std::string swarmScene(const std::string& extra) {
  return "{\"model\": \"swarm\", \"method\": \"auto\", " + extra + "}";
}

// The model's part of a scene's typed params as JSON (its keys as scene files name them).
io::Json modelJson(const std::string& model, SceneParams params) {
  return writeParams([&](ParamVisitor& v) {
    if (model == "balls") balls::visit(v, params.model<balls::Params>());
    if (model == "ripples") ripples::visit(v, params.model<ripples::Params>());
    if (model == "swarm") sim::visit(v, params.model<sim::SwarmParams>());
  });
}

io::Json::json_pointer pointer(std::string key) {  // "engine.dt" -> /engine/dt
  std::replace(key.begin(), key.end(), '.', '/');
  return io::Json::json_pointer("/" + key);
}

// The dotted keys of the leaves where `a` and `b` differ.
std::vector<std::string> changedKeys(const io::Json& a, const io::Json& b, const std::string& prefix = "") {
  std::vector<std::string> out;
  for (const auto& [key, value] : a.items()) {
    if (value.is_object()) {
      for (const std::string& k : changedKeys(value, b.at(key), prefix + key + ".")) out.push_back(k);
    } else if (value != b.at(key)) {
      out.push_back(prefix + key);
    }
  }
  return out;
}

}  // namespace

TEST(SelectCheapest, PicksTheCheapestRowWhoseErrorMeetsTheBoundWithTheMargin) {
  std::vector<Candidate> rows = {row("a", 1.0, 1.0, 0.9e-3), row("a", 0.5, 2.0, 0.2e-3), row("b", 1.0, 4.0, 1e-6)};
  const Selection s = selectCheapest(rows, {{"energyDrift", 1e-3}}, "s");
  // 0.9e-3 meets 1e-3 but not with the margin: the pick is the next cheapest.
  EXPECT_EQ(s.chosen, &rows[1]);
  EXPECT_EQ(s.mostAccurate, &rows[2]);
  EXPECT_LT(s.chosen->cost, s.mostAccurate->cost);
}

TEST(SelectCheapest, ARowCountsWithTheWorstErrorOfItsFamilyAtSmallerSteps) {
  // Round-off: the family's smallest step is worse than the middle one. The engine may run a
  // smaller step than picked, so the middle and the largest step inherit that error.
  std::vector<Candidate> rows = {row("rk4", 0.1, 1.0, 1e-5), row("rk4", 0.05, 2.0, 1e-6), row("rk4", 0.02, 5.0, 4e-4),
                                 row("verlet", 0.01, 3.0, 1e-4)};
  const Selection s = selectCheapest(rows, {{"energyDrift", 5e-4}}, "s");
  EXPECT_EQ(rows[0].guaranteed[0], 4e-4);
  EXPECT_EQ(rows[1].guaranteed[0], 4e-4);
  EXPECT_EQ(s.chosen, &rows[3]);
}

TEST(SelectCheapest, UnstableRowsAreNeverPickedAndPoisonLargerStepsOfTheirFamily) {
  std::vector<Candidate> rows = {row("a", 1.0, 1.0, 1e-9), row("a", 0.5, 2.0, 1e-9, false), row("b", 1.0, 3.0, 1e-3)};
  EXPECT_EQ(selectCheapest(rows, {{"maxOverlap", 0.01}}, "s").chosen, &rows[2]);
}

TEST(SelectCheapest, NoRowMeetingTheBoundIsAOneLineErrorNamingTheBest) {
  std::vector<Candidate> rows = {row("a", 1.0, 1.0, 0.1), row("b", 1.0, 2.0, 0.01)};
  try {
    selectCheapest(rows, {{"phaseError", 1e-6}}, "s.json: scene.accuracy");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.json: scene.accuracy.phaseError 1e-06 cannot be met by any measured "
                                          "setting; best is b at 1.000000 with 0.01 (needs <= 5e-07",
                                          0),
              0u)
        << e.what();
  }
}

TEST(ResolveAuto, ShippedDataGivesEachModelAPickCheaperThanTheMostAccurate) {
  for (const std::string name : {"swarm-auto", "ripples-auto", "balls-auto"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(resolveScenePath(name));
    ASSERT_TRUE(scene.autoChoice);
    const AutoChoice& c = *scene.autoChoice;
    EXPECT_LT(c.costMsPerSimS, c.mostAccurateCost) << c.summary();
    EXPECT_NE(c.device, "");
    EXPECT_EQ(c.summary().rfind("auto: picked " + c.picked + " (", 0), 0u);
    EXPECT_EQ(c.summary().find('\n'), std::string::npos);
    // Each setting writes the field its key names: the most accurate pick, written over this
    // one, changes no key outside its settings, and every key names a parameter.
    const io::Json picked = modelJson(scene.model, scene.params);
    const io::Json best = modelJson(scene.model, c.mostAccurateParams);
    std::vector<std::string> keys;
    for (const Setting& s : c.settings) {
      keys.push_back(s.key);
      EXPECT_TRUE(picked.contains(pointer(s.key))) << s.key;
    }
    for (const std::string& key : changedKeys(picked, best))
      EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key << " changed but is not a setting";
  }
}

TEST(ResolveAuto, EveryMetricReadsItsShippedStudy) {
  for (const Metric& s : metrics()) {
    SCOPED_TRACE(s.key);
    for (const std::string& study : s.studies) {
      const std::filesystem::path file = accuracyDir() / (study + ".csv");
      const io::CsvTable table(file);
      EXPECT_TRUE(table.has(s.column)) << file;
      EXPECT_NE(table.text(0, "device"), "");
    }
  }
}

TEST(ResolveAuto, MistakesAreOneLineErrorsNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {swarmScene("\"accuracy\": {\"energyDrfit\": 1e-3}"),
       "s.json: scene.accuracy.energyDrfit: unknown key (known for swarm: energyDrift)"},
      {swarmScene("\"accuracy\": {\"maxOverlap\": 0.02}"),
       "s.json: scene.accuracy.maxOverlap is a balls metric; a swarm scene states energyDrift"},
      {swarmScene("\"accuracy\": {\"energyDrift\": 0}"),
       "s.json: scene.accuracy.energyDrift = 0 is out of range (0, 1]"},
      {swarmScene("\"accuracy\": {\"energyDrift\": 2}"),
       "s.json: scene.accuracy.energyDrift = 2 is out of range (0, 1]"},
      {swarmScene("\"accuracy\": {\"energyDrift\": \"small\"}"),
       "s.json: scene.accuracy.energyDrift: expected a number, got \"small\""},
      {swarmScene("\"accuracy\": 0.001"), "s.json: scene.accuracy: expected an object {...}, got number"},
      {swarmScene("\"params\": {}"),
       "s.json: scene.method = 'auto' needs scene.accuracy, the error the scene accepts (swarm: energyDrift)"},
      {"{\"model\": \"swarm\", \"accuracy\": {\"energyDrift\": 1e-3}}",
       "s.json: scene.accuracy is read only with \"method\": \"auto\" (add it, or remove accuracy)"},
      {"{\"model\": \"swarm\", \"method\": \"fast\"}", "s.json: scene.method = 'fast' is not one of: params, auto"},
      {"{\"model\": \"life\", \"method\": \"auto\", \"accuracy\": {\"energyDrift\": 1e-3}}",
       "s.json: scene.method = 'auto': no measured data for model 'life' (auto works for balls, ripples and swarm)"},
      {swarmScene("\"accuracy\": {\"energyDrift\": 1e-3}, \"params\": {\"integrator\": \"rk4\"}"),
       "s.json: params.integrator is picked by \"method\": \"auto\"; remove it (or the auto method)"},
      {"{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": {\"phaseError\": 0.01}}",
       "s.json: scene.accuracy: state the shortest wave that must keep its speed, as wavelength (m; the pick may "
       "change the grid) or wavelengthCells (cells of the scene's grid), one of them"},
      {"{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": {\"phaseError\": 0.01, \"wavelengthCells\": 1}}",
       "s.json: scene.accuracy.wavelengthCells = 1 is out of range [2, 100000]"},
      {"{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": {\"phaseError\": 0.01, \"wavelengthCells\": 3}}",
       "s.json: scene.accuracy.wavelengthCells 3 is below the coarsest measured ("},
      {"{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": {\"phaseError\": 0.01, \"wavelength\": 1}, "
       "\"params\": {\"rule\": \"seed\"}}",
       "s.json: scene.accuracy: the dispersion data measures the wave rule; this scene uses rule 'seed'"},
      {"{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": {\"phaseError\": 1e-6, \"wavelengthCells\": 8}}",
       "s.json: scene.accuracy.phaseError 1e-06 cannot be met by any measured setting; best is C <= "},
      {"{\"model\": \"balls\", \"method\": \"auto\", \"accuracy\": {\"maxOverlap\": 0.02, \"restitutionError\": 0.1}}",
       "s.json: scene.accuracy: restitutionError (balls-restitution) and maxOverlap (balls-settle) are measured by "
       "different studies; state bounds of one study"},
  };
  for (const auto& [json, message] : cases) {
    SCOPED_TRACE(json);
    const std::string got = sceneError(json);
    EXPECT_EQ(got.rfind(message, 0), 0u) << got;
    EXPECT_EQ(got.find('\n'), std::string::npos) << got;
  }
}

TEST(ResolveAuto, FixedGridRipplesPickOnlyTheCourantNumber) {
  const Scene s = parseScene(io::parseJson("{\"model\": \"ripples\", \"method\": \"auto\", \"accuracy\": "
                                           "{\"phaseError\": 0.05, \"wavelengthCells\": 20}, \"params\": "
                                           "{\"width\": 64, \"height\": 64}}",
                                           "s.json"),
                             "s.json");
  ASSERT_TRUE(s.autoChoice);
  const ripples::Params& p = s.params.model<ripples::Params>();
  EXPECT_EQ(p.width, 64);  // the scene's grid stays
  EXPECT_EQ(p.cellSize, ripples::Params{}.cellSize);
  for (const Setting& setting : s.autoChoice->settings) EXPECT_NE(setting.key, "cell_size");
  EXPECT_TRUE(p.autoSubsteps);
  EXPECT_LE(p.courantTarget, kStabilityMargin + 1e-6);
}

// `tidepool sweep <study> --ship` copies the rows into assets/accuracy (here a temporary assets
// folder) for the studies auto reads, and only for those; quick runs are refused before anything runs.
TEST(ShipStudy, SweepShipCopiesTheCsvOfStudiesAutoReads) {
  test::TempDir assets;
  const std::string results = std::string(TIDEPOOL_SOURCE_DIR) + "/bench/results";
  const std::string env = "TIDEPOOL_ASSET_DIR=" + assets.path().string();
  auto ok =
      test::runTidepool({"sweep", "swarm-orbit", "--from-csv", "--no-chart", "--ship", "--csv-dir", results}, {env});
  ASSERT_EQ(ok.exitCode, 0) << ok.out << ok.err;
  EXPECT_EQ(io::readTextFile(assets / "accuracy/swarm-orbit.csv"), io::readTextFile(results + "/swarm-orbit.csv"));
  auto other = test::runTidepool(
      {"sweep", "ripples-stability", "--from-csv", "--no-chart", "--ship", "--csv-dir", results}, {env});
  ASSERT_EQ(other.exitCode, 0) << other.out << other.err;
  EXPECT_EQ(other.out.find("shipped"), std::string::npos) << other.out;
  EXPECT_FALSE(std::filesystem::exists(assets / "accuracy/ripples-stability.csv"));
  auto quick =
      test::runTidepool({"sweep", "swarm-orbit", "--quick", "--ship", "--csv-dir", assets.path().string()}, {env});
  EXPECT_NE(quick.exitCode, 0);
  EXPECT_EQ(quick.errLines().size(), 1u) << quick.err;
  EXPECT_NE(quick.err.find("--ship"), std::string::npos) << quick.err;
}

TEST(ShipStudy, TheShipScriptRunsEveryStudyAutoReads) {
  const std::string script = io::readTextFile(std::string(TIDEPOOL_SOURCE_DIR) + "/scripts/ship-accuracy.sh");
  const std::size_t start = script.find("\nstudies=(");
  ASSERT_NE(start, std::string::npos);
  std::istringstream list(script.substr(start + 10, script.find(')', start) - start - 10));
  std::vector<std::string> listed;
  for (std::string s; list >> s;) listed.push_back(s);
  // Every study auto reads that `tidepool sweep` can run is listed, and nothing else.
  const std::vector<std::string> shipped = shippedStudies();
  for (const std::string& s : listed) EXPECT_NE(std::find(shipped.begin(), shipped.end(), s), shipped.end()) << s;
  for (const sweep::Study& study : sweep::studies())
    if (std::find(shipped.begin(), shipped.end(), study.name) != shipped.end()) {
      EXPECT_NE(std::find(listed.begin(), listed.end(), study.name), listed.end()) << study.name;
    }
}
