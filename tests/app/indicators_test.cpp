// The window's counters and keys without a window: a rate over 500 ms windows (refreshed once a
// window, across a model reset) and the key table (the original apps' S, D, Space; no key bound
// twice to different actions; the letters left to the stage).
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <set>

#include "app/indicators.h"
#include "app/key_bindings.h"

using namespace tidepool;

TEST(Indicators, StepsPerSecondOverHalfSecondWindows) {
  RateCounter c;  // 0.5 s windows
  std::uint64_t steps = 0;
  double t = 10.0;
  c.sample(t, steps);
  EXPECT_EQ(c.perSecond(), 0.0) << "nothing before the first window closes";
  // 60 frames a second, 8 steps a frame: 480 steps/s, shown once 0.5 s have passed.
  int refreshes = 0;
  for (int frame = 1; frame <= 120; ++frame) {
    t += 1.0 / 60.0;
    steps += 8;
    c.sample(t, steps);
    if (c.fresh()) {
      ++refreshes;
      EXPECT_NEAR(c.perSecond(), 480.0, 1e-6) << "frame " << frame;
    } else if (frame < 30) {
      EXPECT_EQ(c.perSecond(), 0.0) << "frame " << frame << ": the value holds until the window ends";
    }
  }
  EXPECT_GE(refreshes, 3);
  EXPECT_LE(refreshes, 4) << "about every 500 ms over 2 s";
  // The rate follows a change within two windows and holds between refreshes.
  double shown = c.perSecond();
  for (int frame = 0; frame < 45; ++frame) {
    t += 1.0 / 60.0;
    steps += 2;  // 120 steps/s
    c.sample(t, steps);
    if (!c.fresh()) EXPECT_EQ(c.perSecond(), shown) << "frame " << frame;
    shown = c.perSecond();
  }
  EXPECT_NEAR(c.perSecond(), 120.0, 1e-6);
}

TEST(Indicators, AResetCountsOnFromZero) {
  RateCounter c(1.0);
  c.sample(0.0, 1000);
  c.sample(0.5, 1100);  // 100 steps
  c.sample(0.6, 30);    // the model was reset: 30 steps since
  c.sample(1.0, 130);   // 100 more
  EXPECT_TRUE(c.fresh());
  EXPECT_NEAR(c.perSecond(), 230.0, 1e-9) << "100 + 30 + 100 steps in 1 s";
}

TEST(Indicators, FramesCountedOncePerUpdate) {
  Indicators ind;
  StageIndicators s;
  for (int i = 0; i <= 30; ++i) {
    s.steps = std::uint64_t(i) * 4;
    ind.update(i / 30.0, s);
  }
  EXPECT_NEAR(ind.frames.perSecond(), 30.0, 1e-6);
  EXPECT_NEAR(ind.steps.perSecond(), 120.0, 1e-6);
}

TEST(KeyBindings, TheOriginalAppsKeys) {
  EXPECT_EQ(appAction(GLFW_KEY_S), KeyAction::TogglePanel) << "S hides the panel, as the original";
  EXPECT_EQ(appAction(GLFW_KEY_H), KeyAction::TogglePanel);
  EXPECT_EQ(appAction(GLFW_KEY_D), KeyAction::ToggleTimings);
  EXPECT_EQ(appAction(GLFW_KEY_SPACE), KeyAction::Pause);
  EXPECT_EQ(appAction(GLFW_KEY_R), KeyAction::Restart);
  EXPECT_EQ(appAction(GLFW_KEY_F11), KeyAction::Fullscreen);
  EXPECT_EQ(appAction(GLFW_KEY_F12), KeyAction::Screenshot);
  EXPECT_EQ(appAction(GLFW_KEY_ESCAPE), KeyAction::Quit);
  // The stages' letters stay theirs: life C (centre), N (new rules), W (save rules); water M.
  for (int k : {GLFW_KEY_C, GLFW_KEY_N, GLFW_KEY_W, GLFW_KEY_M}) EXPECT_FALSE(appAction(k)) << char(k);
}

TEST(KeyBindings, EachKeyOnceAndEveryActionReachable) {
  std::set<int> keys;
  std::set<KeyAction> actions;
  for (const KeyBinding& b : keyBindings()) {
    EXPECT_TRUE(keys.insert(b.key).second) << b.name << " is bound twice";
    EXPECT_EQ(appAction(b.key), b.action) << b.name;
    actions.insert(b.action);
  }
  EXPECT_EQ(actions.size(), std::size_t(KeyAction::ToggleTimings) + 1) << "an action without a key";
}
