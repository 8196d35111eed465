// ImGui panels of the window app. They only read state or edit plain structs and flags.
#pragma once

#include <string>
#include <vector>

#include "gl/gpu_profiler.h"
#include "scene/scene.h"

namespace tidepool {

// Recent values for the live plots (a ring of the last kHistory frames).
struct History {
  static constexpr int kHistory = 240;
  std::vector<float> costMs = std::vector<float>(kHistory, 0.0f);  // GPU ms per frame
  std::vector<float> metric = std::vector<float>(kHistory, 0.0f);  // the model's error metric
  // The scene's probes: one ring per column, restarted when the columns change; NaN is kept as 0
  // and shown by the last readings.
  ProbeReadings probes;
  std::vector<std::vector<float>> probeRings;
  int next = 0;
  void push(float cost, float value, ProbeReadings readings = {});
};

struct UiState {
  bool paused = false;
  int stepsPending = 0;  // . presses and Step clicks not yet taken: one step a frame while paused
  bool resetRequested = false;
  bool reloadRequested = false;
  bool screenshotRequested = false;
  bool showUi = true;                // S (or H): the panels
  bool showTimings = false;          // D: FPS and the GPU passes' times (the panel's "GPU timings")
  bool showIndicators = true;        // the overlay: FPS, steps/s, count, grid, axes
  bool fullscreenRequested = false;  // F11 or the panel's button
  bool recoverRequested = false;
  bool checkpointRequested = false;  // F6
  std::string divergence;            // the model\'s blow-up report; the run is paused while it is set
  std::string message;               // last action's result (reload, screenshot)
  bool messageIsError = false;
  History history;
  float panelRight = 0, panelHeight = 0;  // the panel as drawn last, pixels (0: hidden or collapsed)
};

// Main panel: scene, then collapsible sections (run, plots, GPU timings, parameters, tools), at
// the left edge in a fixed width, scrolling when taller than the framebuffer (app/panel_layout.h).
// Returns true when parameters changed. `autosaveEvery`: the checkpoint autosave period,
// simulated s (0: off).
bool drawMainPanel(const Scene& scene, Stage& stage, const gl::GpuProfiler& profiler, UiState& ui,
                   float& autosaveEvery);

// What runs now (Stage::running(), else the scene's model), as the panel's first line and the
// window's title say it; the title follows it when M or N changes it: "tidepool - Dam break [fluid]".
std::string runningLabel(const Scene& scene, const Stage& stage);
std::string windowTitle(const std::string& sceneName, const std::string& running);
// ", model auto" while the model running is the one "model": "auto" picked; "" once M switched away.
std::string autoModelNote(const Scene& scene, const std::string& running);

}  // namespace tidepool
