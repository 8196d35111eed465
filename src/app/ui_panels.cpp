#include "app/ui_panels.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "app/panel_layout.h"
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

void History::push(float cost, float value, ProbeReadings readings) {
  if (readings.columns != probes.columns)
    probeRings.assign(readings.columns.size(), std::vector<float>(kHistory, 0.0f));
  for (std::size_t k = 0; k < probeRings.size(); ++k) {
    const double v = k < readings.values.size() ? readings.values[k] : NAN;
    probeRings[k][std::size_t(next)] = std::isfinite(v) ? float(v) : 0.0f;
  }
  probes = std::move(readings);
  costMs[std::size_t(next)] = cost;
  metric[std::size_t(next)] = value;
  next = (next + 1) % kHistory;
}

namespace {
// Each plot under its name, the full width of the panel (a long name is never clipped).
void livePlots(const Stage& stage, const UiState& ui) {
  const History& h = ui.history;
  const auto [name, value] = stage.liveMetric();
  if (!name.empty()) {
    ImGui::TextUnformatted(name.c_str());
    const std::string overlay = plotOverlay(value);  // nothing until the model has measured
    ImGui::PlotLines("##metric", h.metric.data(), History::kHistory, h.next, overlay.c_str(), FLT_MAX, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, 40));
  }
  ImGui::TextUnformatted("GPU ms/frame");
  ImGui::PlotLines("##cost", h.costMs.data(), History::kHistory, h.next, nullptr, 0.0f, FLT_MAX,
                   ImVec2(ImGui::GetContentRegionAvail().x, 40));
}
}  // namespace

namespace {
// "method": "auto" (or "model": "auto"): what was picked at load, against what, and what the most
// accurate would cost.
void autoChoicePanel(const AutoChoice& c, const std::string& running) {
  ImGui::PushTextWrapPos(0.0f);
  if (!c.model.empty() && c.model != running) {  // M switched away from the model auto picked
    ImGui::TextDisabled("model auto picked %s; M switched to %s, whose accuracy is unchecked", c.model.c_str(),
                        running.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
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

std::string autoModelNote(const Scene& scene, const std::string& running) {
  const bool picked = scene.autoChoice && !scene.autoChoice->model.empty() && scene.autoChoice->model == running;
  return picked ? ", model auto" : "";
}

namespace {
// Buttons flow left to right and wrap to the next line where the next one would not fit.
class ButtonRow {
 public:
  bool button(const char* label) {
    place(ImGui::CalcTextSize(label).x + 2 * ImGui::GetStyle().FramePadding.x);
    return ImGui::Button(label);
  }
  bool checkbox(const char* label, bool* value) {
    place(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x);
    return ImGui::Checkbox(label, value);
  }

 private:
  void place(float width) {
    if (m_first) {
      m_first = false;
      return;
    }
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float right = ImGui::GetItemRectMax().x + spacing + width;
    if (right <= ImGui::GetWindowContentRegionMax().x + ImGui::GetWindowPos().x) ImGui::SameLine();
  }
  bool m_first = true;
};

void wrapped(const ImVec4& colour, const std::string& text) {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(colour, "%s", text.c_str());
  ImGui::PopTextWrapPos();
}

// The scene's probes, one plot per column under its name (sim/water/probes.h), or why none.
void probePlots(const History& h) {
  if (!h.probes.error.empty()) wrapped(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "probes: " + h.probes.error);
  for (std::size_t k = 0; k < h.probeRings.size(); ++k) {
    ImGui::TextUnformatted(h.probes.columns[k].c_str());
    const std::string overlay = plotOverlay(k < h.probes.values.size() ? h.probes.values[k] : NAN);
    ImGui::PushID(int(k));
    ImGui::PlotLines("##probe", h.probeRings[k].data(), History::kHistory, h.next, overlay.c_str(), FLT_MAX, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, 30));
    ImGui::PopID();
  }
}

// The model's status, each "; " clause on its own lines, broken only after ", " so a wrap never
// splits a number ("... h = 0.\n03564 m" is what ImGui's wrap at '.' would make of it).
void statusLines(const std::string& status) {
  const ImVec4 colour = ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
  const float width = ImGui::GetContentRegionAvail().x;
  for (std::size_t from = 0; from < status.size();) {
    const std::size_t end = std::min(status.find("; ", from), status.size());
    std::string line;
    for (std::size_t at = from; at < end;) {
      const std::size_t comma = std::min(status.find(", ", at), end);
      const std::size_t next = std::min(comma + 2, end);  // the piece keeps its ", "
      const std::string piece = status.substr(at, next - at);
      if (!line.empty() && ImGui::CalcTextSize((line + piece).c_str()).x > width) {
        wrapped(colour, line);
        line.clear();
      }
      line += piece;
      at = next;
    }
    if (!line.empty()) wrapped(colour, line);
    from = end + 2;
  }
}

void runSection(Stage& stage, UiState& ui) {
  ButtonRow row;
  row.checkbox("Pause (Space)", &ui.paused);
  if (row.button("Step (.)")) ++ui.stepsPending;
  if (row.button("Restart (R)")) ui.resetRequested = true;
  if (row.button("Screenshot (F12)")) ui.screenshotRequested = true;
  if (row.button("Fullscreen (F11)")) ui.fullscreenRequested = true;
  row.checkbox("Indicators", &ui.showIndicators);
  if (const std::string share = stage.shareText(); !share.empty() && row.button("Copy share code")) {
    ImGui::SetClipboardText(share.c_str());  // the GLFW backend: glfwSetClipboardString
    ui.message =
        "share code copied (" + std::to_string(share.size()) + " characters): tidepool run life --rules <code>";
    ui.messageIsError = false;
  }
}

void toolsSection(UiState& ui, float& autosaveEvery) {
  ButtonRow row;
  if (row.button("Reload shaders (F5)")) ui.reloadRequested = true;
  if (row.button("Save checkpoint (F6)")) ui.checkpointRequested = true;
  ImGui::DragFloat("autosave every (sim s)", &autosaveEvery, 0.1f, 0.0f, 3600.0f, autosaveEvery > 0 ? "%.2f" : "off");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a checkpoint at every multiple of this simulated time; 0: off");
}
}  // namespace

bool drawMainPanel(const Scene& scene, Stage& stage, const gl::GpuProfiler& profiler, UiState& ui,
                   float& autosaveEvery) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const PanelLayout layout = panelLayout(int(viewport->Size.x), int(viewport->Size.y));
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + layout.x, viewport->Pos.y + layout.y), ImGuiCond_Always);
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize;
  if (layout.sidebar) {
    ImGui::SetNextWindowSize(ImVec2(layout.width, layout.maxHeight), ImGuiCond_Always);
  } else {
    ImGui::SetNextWindowSizeConstraints(ImVec2(layout.width, 0), ImVec2(layout.width, layout.maxHeight));
    flags |= ImGuiWindowFlags_AlwaysAutoResize;
  }
  const bool open = ImGui::Begin("tidepool", nullptr, flags);
  ui.panelRight = open ? ImGui::GetWindowPos().x + ImGui::GetWindowWidth() - viewport->Pos.x : 0.0f;
  ui.panelHeight = ImGui::GetWindowHeight();
  bool changed = false;
  if (open) {
    ImGui::PushItemWidth(-layout.labelWidth);
    const std::string running = runningLabel(scene, stage);
    ImGui::Text("%s  [%s%s]", scene.name.c_str(), running.c_str(), autoModelNote(scene, running).c_str());
    statusLines(stage.status());
    ImGui::Text("simulated time %.3f s", stage.simTime());
    if (!ui.divergence.empty()) {
      wrapped(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), ui.divergence);
      if (ImGui::Button("Halve dt and resume from the last good state")) ui.recoverRequested = true;
    }
    if (!ui.message.empty())
      wrapped(ui.messageIsError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f), ui.message);
    if (ImGui::CollapsingHeader("Run", ImGuiTreeNodeFlags_DefaultOpen)) runSection(stage, ui);
    if (ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) {
      livePlots(stage, ui);
      probePlots(ui.history);
    }
    ImGui::SetNextItemOpen(ui.showTimings, ImGuiCond_Always);  // D opens and closes it too
    ui.showTimings = ImGui::CollapsingHeader("GPU timings (D)");
    if (ui.showTimings) timingTable(profiler);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
      if (scene.autoChoice) autoChoicePanel(*scene.autoChoice, running);
      ParamEditor editor;
      stage.visitParams(editor);
      changed = editor.changed();
    }
    if (ImGui::CollapsingHeader("Tools")) toolsSection(ui, autosaveEvery);
    ImGui::PopItemWidth();
  }
  ImGui::End();
  return changed;
}

}  // namespace tidepool
