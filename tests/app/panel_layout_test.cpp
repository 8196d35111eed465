// The panel's place and the scene's room, without a window: a sidebar as tall as the framebuffer
// beside the scene in a wide window, a floating panel no taller than the framebuffer in a narrow
// one; the screenshot's wait for a settled layout; the indicator's unit and the plot's value.
#include <gtest/gtest.h>

#include <cmath>

#include "app/panel_layout.h"

using namespace tidepool;

TEST(PanelLayout, ASidebarAsTallAsTheWindowBesideTheScene) {
  for (const auto [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
    const PanelLayout p = panelLayout(w, h);
    EXPECT_TRUE(p.sidebar) << w << "x" << h;
    EXPECT_EQ(p.x, 0.0f);
    EXPECT_EQ(p.maxHeight, float(h)) << "taller sections scroll inside it";
    EXPECT_LE(p.width, 0.4f * float(w)) << "the panel takes under 40% of the width";
    EXPECT_GE(p.width - p.labelWidth, 150.0f) << "room for the widgets beside 20-character labels";
    const SceneArea a = sceneArea(w, p.x + p.width);
    EXPECT_GE(a.x, int(p.width)) << "the scene starts right of the panel";
    EXPECT_EQ(a.x + a.width, w);
  }
}

TEST(PanelLayout, ANarrowWindowGetsAFloatingPanelWithinItsHeight) {
  const PanelLayout p = panelLayout(640, 480);
  EXPECT_FALSE(p.sidebar);
  EXPECT_GT(p.y, 0.0f);
  EXPECT_LE(p.y + p.maxHeight, 480.0f) << "the bottom of the panel (Export) stays in the window";
  const SceneArea a = sceneArea(640, p.x + p.width);
  EXPECT_EQ(a.x, 0) << "too little room beside it: the scene keeps the whole window";
  EXPECT_EQ(a.width, 640);
}

TEST(PanelLayout, AHiddenOrCollapsedPanelLeavesTheWholeWindow) {
  const SceneArea a = sceneArea(1280, 0.0f);
  EXPECT_EQ(a.x, 0);
  EXPECT_EQ(a.width, 1280);
}

TEST(PanelLayout, TheScreenshotWaitsForTwoFramesOfTheSameSize) {
  LayoutWatch w;
  w.see(384, 0);  // ImGui's first frame: measured, not yet sized
  EXPECT_FALSE(w.settled());
  w.see(384, 720);
  EXPECT_FALSE(w.settled());
  w.see(384, 720);
  EXPECT_FALSE(w.settled());
  w.see(384, 720);
  EXPECT_TRUE(w.settled());
  w.see(384, 540);  // a section opened
  EXPECT_FALSE(w.settled());
}

TEST(PanelLayout, GridModelsCountCells) {
  StageIndicators s;
  s.particles = 4776;
  EXPECT_EQ(countText(s), "4776 particles");
  s.particles = 262144;
  s.countsCells = true;
  EXPECT_EQ(countText(s), "262144 cells");
}

TEST(PanelLayout, ThePlotShowsNoValueBeforeTheFirstMeasurement) {
  EXPECT_EQ(plotOverlay(NAN), "");
  EXPECT_EQ(plotOverlay(INFINITY), "");
  EXPECT_EQ(plotOverlay(0.0), "0");
  EXPECT_EQ(plotOverlay(0.3705123), "0.3705");
}
