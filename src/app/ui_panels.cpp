#include "app/ui_panels.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "app/param_editor.h"

namespace tidepool {
namespace {

void timingTable(const gl::GpuProfiler& profiler) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::Text("%.1f FPS  (%.2f ms/frame CPU+GPU)", io.Framerate, 1000.0f / std::max(io.Framerate, 1e-3f));
  if (ImGui::BeginTable("gpu", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("GPU pass");
    ImGui::TableSetupColumn("ms");
    ImGui::TableHeadersRow();
    for (const auto& pass : profiler.passes()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(pass.name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", pass.smoothedMs);
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", profiler.totalSmoothedMs());
    ImGui::EndTable();
  }
}

}  // namespace

void History::push(float cost, float value) {
  costMs[std::size_t(next)] = cost;
  metric[std::size_t(next)] = value;
  next = (next + 1) % kHistory;
}

namespace {
void livePlots(const Stage& stage, const UiState& ui) {
  const History& h = ui.history;
  ImGui::PlotLines("GPU ms/frame", h.costMs.data(), History::kHistory, h.next, nullptr, 0.0f, FLT_MAX, ImVec2(0, 48));
  const auto [name, value] = stage.liveMetric();
  if (!name.empty()) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.4g", value);
    ImGui::PlotLines(name.c_str(), h.metric.data(), History::kHistory, h.next, overlay, FLT_MAX, FLT_MAX,
                     ImVec2(0, 48));
  }
}
}  // namespace

namespace {
// "method": "auto" (or "model": "auto"): what was picked at load, against what, and what the most
// accurate would cost.
void autoChoicePanel(const AutoChoice& c) {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "%s", c.headline().c_str());
  ImGui::TextDisabled("%s auto: %.3g ms per simulated s (most accurate: %s, %.3g)",
                      c.model.empty() ? "method" : "model", c.costMsPerSimS, c.mostAccurate.c_str(),
                      c.mostAccurateCost);
  ImGui::TextDisabled("data: %s, measured on %s", c.studies.c_str(), c.device.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("set at load; editing the parameters below leaves the accuracy unchecked");
}
}  // namespace

std::string runningLabel(const Scene& scene, const Stage& stage) {
  const std::string running = stage.running();
  return running.empty() ? scene.model : running;
}

std::string windowTitle(const std::string& sceneName, const std::string& running) {
  return "tidepool - " + sceneName + " [" + running + "]";
}

bool drawMainPanel(const Scene& scene, Stage& stage, const gl::GpuProfiler& profiler, UiState& ui,
                   float& autosaveEvery) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(340, 0), ImVec2(520, 10000));
  ImGui::Begin("tidepool", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const bool modelAuto = scene.autoChoice && !scene.autoChoice->model.empty();
  ImGui::Text("%s  [%s%s]", scene.name.c_str(), runningLabel(scene, stage).c_str(), modelAuto ? ", model auto" : "");
  if (const std::string s = stage.status(); !s.empty()) ImGui::TextDisabled("%s", s.c_str());
  ImGui::Text("simulated time %.3f s", stage.simTime());
  if (ui.showTimings) timingTable(profiler);
  livePlots(stage, ui);
  ImGui::Checkbox("Timings (D)", &ui.showTimings);
  ImGui::SameLine();
  ImGui::Checkbox("Indicators", &ui.showIndicators);
  ImGui::SameLine();
  if (ImGui::Button("Fullscreen (F11)")) ui.fullscreenRequested = true;

  ImGui::Checkbox("Pause (Space)", &ui.paused);
  ImGui::SameLine();
  if (ImGui::Button("Step (.)")) ++ui.stepsPending;
  ImGui::SameLine();
  if (ImGui::Button("Restart (R)")) ui.resetRequested = true;
  if (ImGui::Button("Reload shaders (F5)")) ui.reloadRequested = true;
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (F12)")) ui.screenshotRequested = true;
  if (ImGui::Button("Save checkpoint (F6)")) ui.checkpointRequested = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::DragFloat("autosave every (sim s)", &autosaveEvery, 0.1f, 0.0f, 3600.0f, autosaveEvery > 0 ? "%.2f" : "off");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a checkpoint at every multiple of this simulated time; 0: off");
  if (const std::string share = stage.shareText(); !share.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Copy share code")) {
      ImGui::SetClipboardText(share.c_str());  // the GLFW backend: glfwSetClipboardString
      ui.message =
          "share code copied (" + std::to_string(share.size()) + " characters): tidepool run life --rules <code>";
      ui.messageIsError = false;
    }
  }
  if (!ui.divergence.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", ui.divergence.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Halve dt and resume from the last good state")) ui.recoverRequested = true;
  }
  if (!ui.message.empty()) {
    const ImVec4 colour = ui.messageIsError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(colour, "%s", ui.message.c_str());
    ImGui::PopTextWrapPos();
  }

  bool changed = false;
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (scene.autoChoice) autoChoicePanel(*scene.autoChoice);
    ParamEditor editor;
    stage.visitParams(editor);
    changed = editor.changed();
  }
  ImGui::End();
  return changed;
}

}  // namespace tidepool
