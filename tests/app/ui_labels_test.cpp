// The words the window shows about what runs: the title's model and the ", model auto" note,
// which holds only while the model running is the one "model": "auto" picked; and the rings of
// the probes' live plots.
#include <gtest/gtest.h>

#include "app/ui_panels.h"
#include "scene/scene.h"

using namespace tidepool;

TEST(UiLabels, TheTitleNamesTheSceneAndTheModelRunning) {
  EXPECT_EQ(windowTitle("Dam break", "fluid"), "tidepool - Dam break [fluid]");
}

TEST(UiLabels, ModelAutoIsNotedOnlyWhileItsPickRuns) {
  Scene scene;
  scene.model = "fluid";
  EXPECT_EQ(autoModelNote(scene, "fluid"), "") << "no auto choice";
  scene.autoChoice = AutoChoice{};
  EXPECT_EQ(autoModelNote(scene, "fluid"), "") << "method auto picks no model";
  scene.autoChoice->model = "fluid";
  EXPECT_EQ(autoModelNote(scene, "fluid"), ", model auto");
  EXPECT_EQ(autoModelNote(scene, "balls"), "") << "after M switched to the other water model";
}

// The live plots keep one ring per probe column: a value lands where the frame's other plots'
// do, NaN (a pressure before the first step) as 0, and new columns (a probe added in the panel)
// start the rings anew.
TEST(UiLabels, ProbePlotsKeepARingPerColumnAndRestartWhenTheColumnsChange) {
  History h;
  h.push(1.0f, 0.0f, {.columns = {"gauge0_height_m", "pressure1_pa"}, .values = {0.2, NAN}});
  h.push(1.0f, 0.0f, {.columns = {"gauge0_height_m", "pressure1_pa"}, .values = {0.21, 980.0}});
  ASSERT_EQ(h.probeRings.size(), 2u);
  EXPECT_EQ(h.probeRings[0][0], 0.2f);
  EXPECT_EQ(h.probeRings[0][1], 0.21f);
  EXPECT_EQ(h.probeRings[1][0], 0.0f) << "NaN kept as 0";
  EXPECT_EQ(h.probeRings[1][1], 980.0f);
  EXPECT_EQ(h.probes.values[0], 0.21) << "the last readings, for the plots' labels";
  h.push(1.0f, 0.0f, {.columns = {"force0_normal_n"}, .values = {39.0}});
  ASSERT_EQ(h.probeRings.size(), 1u);
  EXPECT_EQ(h.probeRings[0][2], 39.0f);
  EXPECT_EQ(h.probeRings[0][1], 0.0f) << "a new column starts empty";
  h.push(1.0f, 0.0f, {});
  EXPECT_TRUE(h.probeRings.empty()) << "no probes: no plots";
}
