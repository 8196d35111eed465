// Where the window's panel goes and what room it leaves the scene: a fixed-width sidebar the
// framebuffer's height at the left edge (it scrolls when its sections are taller), the scene drawn
// in the columns to its right, so the panel hides none of it. A window too narrow for that gets
// the panel floating over the scene, as tall as its content up to the framebuffer's height.
// Pure arithmetic, in framebuffer pixels.
#pragma once

#include <string>

#include "scene/stage.h"

namespace tidepool {

struct PanelLayout {
  float x = 0, y = 0;    // top-left corner
  float width = 0;       // fixed: labels get labelWidth, widgets the rest
  float maxHeight = 0;   // the framebuffer's height (less the margins when floating); taller content scrolls
  float labelWidth = 0;  // the column right of each widget for its label
  bool sidebar = false;  // the full height at the edge, beside the scene; else floating over it
};
PanelLayout panelLayout(int fbWidth, int fbHeight);

// The framebuffer columns the scene is drawn in: right of the panel when it leaves the scene at
// least kMinSceneShare of the width, else (a small window, a collapsed or hidden panel) all of it.
struct SceneArea {
  int x = 0, width = 0;
};
inline constexpr float kMinSceneShare = 0.6f;
SceneArea sceneArea(int fbWidth, float panelRight);  // panelRight: 0 when the panel is hidden or collapsed

// ImGui sizes a new or changed window over a frame or two: the screenshot that ends a run waits
// until the panel's size has held for two frames.
class LayoutWatch {
 public:
  void see(float width, float height);  // once a frame, the panel's size (0, 0: none)
  bool settled() const { return m_stable >= 2; }

 private:
  float m_width = -1, m_height = -1;
  int m_stable = 0;
};

std::string countText(const StageIndicators& s);  // "4776 particles", "262144 cells"
std::string plotOverlay(double value);            // the live plot's value; "" until there is one (NaN)

}  // namespace tidepool
