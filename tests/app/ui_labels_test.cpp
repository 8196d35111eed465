// The words the window shows about what runs: the title's model and the ", model auto" note,
// which holds only while the model running is the one "model": "auto" picked.
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
