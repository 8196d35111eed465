// The interactive window: GLFW + Dear ImGui, live parameter tuning, per-pass GPU times.
// Keys: Space pause, . single step, R reset, F5 reload shaders, F12 screenshot, H hide UI, Esc quit.
// Other letters go to the stage (Stage::key; life: C centre, N new rules, S save rules).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "io/json.h"

namespace tidepool {

struct WindowJob {
  std::string scene;  // path or bare name
  int width = 1280, height = 720;
  std::optional<int> maxFrames;      // close after this many frames (scripts, tests)
  std::filesystem::path screenshot;  // written after the last frame when set
  bool debugGl = false;
  bool vsync = true;
  io::Json paramOverrides;  // scene params set from the command line (--rules)
};

int runWindow(const WindowJob& job);  // exit code; throws Error

}  // namespace tidepool
