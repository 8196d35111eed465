#include "app/indicators.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include "app/panel_layout.h"

namespace tidepool {

void RateCounter::sample(double now, std::uint64_t total) {
  m_counted += total >= m_last ? total - m_last : total;  // a drop: the count restarted from zero
  m_last = total;
  m_fresh = false;
  if (!m_started) {
    m_started = true;
    m_windowStart = now;
    m_atStart = m_counted;
    return;
  }
  const double elapsed = now - m_windowStart;
  if (elapsed < m_window) return;
  m_rate = double(m_counted - m_atStart) / elapsed;
  m_windowStart = now;
  m_atStart = m_counted;
  m_fresh = true;
}

void Indicators::update(double now, const StageIndicators& s) {
  frames.sample(now, ++frameCount);
  steps.sample(now, s.steps);
}

void drawIndicators(const Indicators& c, const StageIndicators& s) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x - 10, vp->WorkPos.y + 10), ImGuiCond_Always,
                          ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.45f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("indicators", nullptr, flags)) {
    ImGui::Text("%.1f FPS", c.frames.perSecond());
    const double steps = c.steps.perSecond();
    if (s.steps > 0) ImGui::Text(steps < 10.0 ? "%.1f steps/s" : "%.0f steps/s", steps);  // models that count them
    if (s.particles > 0) ImGui::TextUnformatted(countText(s).c_str());
    if (s.gridCells.x > 0) {
      if (s.gridCells.z > 1)
        ImGui::Text("grid %u x %u x %u, cell %.4g", s.gridCells.x, s.gridCells.y, s.gridCells.z, s.cellSize);
      else
        ImGui::Text("grid %u x %u, cell %.4g", s.gridCells.x, s.gridCells.y, s.cellSize);
    }
  }
  ImGui::End();
}

void drawAxesGizmo(const glm::mat4& view) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  constexpr float kLength = 38.0f, kMargin = 52.0f;
  const ImVec2 origin(vp->WorkPos.x + vp->WorkSize.x - kMargin, vp->WorkPos.y + vp->WorkSize.y - kMargin);
  struct Axis {
    glm::vec3 dir;  // in view space
    ImU32 colour;
    const char* name;
  };
  std::array<Axis, 3> axes = {Axis{glm::mat3(view)[0], IM_COL32(235, 70, 60, 255), "X"},
                              Axis{glm::mat3(view)[1], IM_COL32(90, 210, 80, 255), "Y"},
                              Axis{glm::mat3(view)[2], IM_COL32(70, 130, 245, 255), "Z"}};
  // The farthest first (view space looks down -z), so nearer axes draw over it.
  std::sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) { return a.dir.z < b.dir.z; });
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  draw->AddCircleFilled(origin, kLength + 10.0f, IM_COL32(0, 0, 0, 70));
  for (const Axis& a : axes) {
    const ImVec2 tip(origin.x + kLength * a.dir.x, origin.y - kLength * a.dir.y);  // screen y grows down
    draw->AddLine(origin, tip, a.colour, 2.5f);
    draw->AddText(ImVec2(tip.x - 3.0f + 6.0f * a.dir.x, tip.y - 7.0f - 6.0f * a.dir.y), a.colour, a.name);
  }
}

}  // namespace tidepool
