// The interactive window: GLFW + Dear ImGui, live parameter tuning, per-pass GPU times.
// Keys (app/key_bindings.h): Space pause, . single step, R restart, F5 reload shaders, F6 save a
// checkpoint, F11 fullscreen, F12 screenshot, S (or H) hide the panels, D the timings, Esc quit.
// Other letters go to the stage (Stage::key; life: C centre, N new rules, W save rules).
// Frames are paced with fences (gl/frame_pacer.h): at most job.framesInFlight queued on the GPU.
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
  std::filesystem::path screenshot;  // written after the last frame when set, once the panel has settled
  bool debugGl = false;
  bool vsync = true;
  io::Json paramOverrides;            // scene params set from the command line (--rules, --set); live ones on a resume
  std::filesystem::path resume;       // a checkpoint to start from; empty: the scene's start
  std::filesystem::path checkpoint;   // where F6 and the autosave write; empty: "<scene name>.ckpt" here
  double autosaveEvery = 0;           // simulated s between autosaves (0: off; the panel edits it)
  int framesInFlight = 2;             // frames the CPU may queue ahead of the GPU before it waits
  std::optional<double> fitBudgetMs;  // --fit-gpu: particles.resolution measured for this budget (app/fit_gpu.h)
};

int runWindow(const WindowJob& job);  // exit code; throws Error

}  // namespace tidepool
