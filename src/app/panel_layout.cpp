#include "app/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tidepool {
namespace {
constexpr float kMargin = 10.0f;       // pixels between a floating panel and the framebuffer's edges
constexpr float kMinWidth = 330.0f;    // the widest row of buttons fits
constexpr float kMaxWidth = 420.0f;    // beyond this, widgets only grow
constexpr float kLabelWidth = 150.0f;  // 20 characters of the default 13 px font, the longest label
}  // namespace

PanelLayout panelLayout(int fbWidth, int fbHeight) {
  PanelLayout p;
  p.width = std::clamp(0.3f * float(fbWidth), kMinWidth, kMaxWidth);
  p.labelWidth = kLabelWidth;
  p.sidebar = sceneArea(fbWidth, p.width).x > 0;
  const float margin = p.sidebar ? 0.0f : kMargin;
  p.x = p.y = margin;
  p.maxHeight = std::max(float(fbHeight) - 2.0f * margin, 100.0f);
  return p;
}

SceneArea sceneArea(int fbWidth, float panelRight) {
  const int left = panelRight > 0 ? int(std::ceil(panelRight)) : 0;
  if (left <= 0 || float(fbWidth - left) < kMinSceneShare * float(fbWidth)) return {0, fbWidth};
  return {left, fbWidth - left};
}

void LayoutWatch::see(float width, float height) {
  m_stable = width == m_width && height == m_height ? m_stable + 1 : 0;
  m_width = width;
  m_height = height;
}

std::string countText(const StageIndicators& s) {
  return std::to_string(s.particles) + " " + (s.countsCells ? "cells" : "particles");
}

std::string plotOverlay(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace tidepool
