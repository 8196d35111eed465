// ImGui panels of the window app. They only read state or edit plain structs and flags.
#pragma once

#include <string>

#include "gl/gpu_profiler.h"
#include "scene/scene.h"

namespace tidepool {

struct UiState {
  bool paused = false;
  bool stepOnce = false;
  bool resetRequested = false;
  bool reloadRequested = false;
  bool screenshotRequested = false;
  bool showUi = true;
  bool recoverRequested = false;
  std::string divergence;  // the model\'s blow-up report; the run is paused while it is set
  std::string message;     // last action's result (reload, screenshot)
  bool messageIsError = false;
};

// Main panel: scene, timing table, transport buttons, parameters. Returns true when parameters changed.
bool drawMainPanel(const Scene& scene, Stage& stage, const gl::GpuProfiler& profiler, UiState& ui);

}  // namespace tidepool
