#include "app/window_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <utility>

#include "app/fit_gpu.h"
#include "app/indicators.h"
#include "app/key_bindings.h"
#include "app/key_queue.h"
#include "app/panel_layout.h"
#include "app/ui_panels.h"
#include "app/window_checkpoints.h"
#include "app/window_export.h"
#include "base/log.h"
#include "gl/context_window.h"
#include "gl/frame_pacer.h"
#include "io/png.h"

namespace tidepool {
namespace {

io::Image readWindow(int width, int height) {
  io::Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  std::vector<std::uint8_t> bottomUp(img.rgba.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  const std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y) std::copy_n(&bottomUp[row * (height - 1 - y)], row, &img.rgba[row * y]);
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // the window is opaque
  return img;
}

std::string timestampedName() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "screenshot_%Y%m%d_%H%M%S.png", std::localtime(&t));
  return buf;
}

// The scene sees only its area: cursor and viewport relative to it.
Input readInput(GLFWwindow* window, const SceneArea& area, glm::vec2& lastCursor, float& scroll, float dt) {
  Input in;
  in.dt = dt;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  in.cursor = {float(x) - float(area.x), float(y)};
  in.cursorDelta = in.cursor - lastCursor;
  lastCursor = in.cursor;
  glfwGetFramebufferSize(window, &in.viewport.x, &in.viewport.y);
  in.viewport.x = area.width;
  const bool free = !ImGui::GetIO().WantCaptureMouse;
  in.left = free && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  in.right = free && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  in.middle = free && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  in.scroll = free ? std::exchange(scroll, 0.0f) : 0.0f;
  return in;
}

float g_scroll = 0.0f;               // accumulated by the GLFW callback between frames
std::vector<std::string> g_dropped;  // files dropped on the window since the last frame

void apply(KeyAction action, UiState& ui, GLFWwindow* window) {
  switch (action) {
    case KeyAction::Quit: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case KeyAction::Pause: ui.paused = !ui.paused; break;
    case KeyAction::StepOnce: ++ui.stepsPending; break;
    case KeyAction::Restart: ui.resetRequested = true; break;
    case KeyAction::ReloadShaders: ui.reloadRequested = true; break;
    case KeyAction::SaveCheckpoint: ui.checkpointRequested = true; break;
    case KeyAction::Fullscreen: ui.fullscreenRequested = true; break;
    case KeyAction::Screenshot: ui.screenshotRequested = true; break;
    case KeyAction::TogglePanel: ui.showUi = !ui.showUi; break;
    case KeyAction::ToggleTimings: ui.showTimings = !ui.showTimings; break;
  }
}

// --fit-gpu: the scene at the finest resolution whose frame fits the budget in this window.
Scene fitScene(const std::filesystem::path& file, const WindowJob& job, gl::ShaderLibrary& shaders) {
  FitOptions options;
  options.budgetMs = *job.fitBudgetMs;
  options.width = job.width;
  options.height = job.height;
  return loadScene(file, fitOverrides(file, job.paramOverrides, shaders, options));
}

}  // namespace

int runWindow(const WindowJob& job) {
  const std::filesystem::path file = resolveScenePath(job.scene);
  Scene scene = loadScene(file, job.paramOverrides);
  gl::WindowContext context({job.width, job.height, "tidepool - " + scene.name, job.debugGl, job.vsync, true});
  GLFWwindow* window = context.window();
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  if (job.fitBudgetMs) scene = fitScene(file, job, shaders);
  auto stage = createStage(scene, shaders);
  std::uint64_t frameNumber = 0;  // the frame the window shows, as render numbers it: steps since t = 0
  if (!job.resume.empty()) frameNumber = loadCheckpoint(*stage, scene, job.resume, job.paramOverrides);
  WindowCheckpoints checkpoints(scene, job.checkpoint, job.autosaveEvery, stage->simTime());

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  KeyQueue keys;
  installKeyQueue(window, keys);  // before ImGui's backend, which then chains its key callback to ours
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 430 core");
  glfwSetScrollCallback(window, [](GLFWwindow* w, double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(w, dx, dy);
    g_scroll += float(dy);
  });
  glfwSetDropCallback(window, [](GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
  });

  int fbw = 0, fbh = 0;
  context.framebufferSize(fbw, fbh);
  RenderTarget target(std::max(fbw, 1), std::max(fbh, 1));
  gl::GpuProfiler profiler;
  UiState ui;
  WindowExport exports(shaders);
  const auto show = [&ui](const WindowExport::Message& m) {
    if (m.text.empty()) return;
    ui.message = m.text;
    ui.messageIsError = m.error;
  };
  glm::vec2 lastCursor{0.0f};
  gl::FramePacer pacer(job.framesInFlight);
  Indicators counters;
  std::string title;  // as last set: the title follows what runs (M switches the water model, N life's rules)
  double lastTime = glfwGetTime();
  LayoutWatch layout;  // the screenshot ending a run waits for the panel to settle
  // Past --frames, with --screenshot, frames only lay the panel out: the run holds still.
  constexpr int kMaxSettleFrames = 10;

  for (int frame = 0; !context.shouldClose(); ++frame) {
    pacer.waitForSlot();  // before reading input: what the frame shows is as fresh as the GPU allows
    glfwPollEvents();
    for (const int k : keys.take()) {  // every press since the last frame, in order, however long it was
      if (const std::optional<KeyAction> action = appAction(k))
        apply(*action, ui, window);
      else if (k >= GLFW_KEY_A && k <= GLFW_KEY_Z)  // other letters are the model's (life: C, N, W)
        stage->key('A' + (k - GLFW_KEY_A));
    }
    if (std::exchange(ui.fullscreenRequested, false) && !context.setFullscreen(!context.fullscreen())) {
      ui.message = "no monitor to go fullscreen on";
      ui.messageIsError = true;
    }
    const double now = glfwGetTime();
    const float dt = float(std::min(now - lastTime, 0.25));  // real time; a stall does not fling the camera
    lastTime = now;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const StageIndicators shown = stage->indicators();
    counters.update(now, shown);
    ui.panelRight = ui.panelHeight = 0.0f;
    if (ui.showUi) {
      drawMainPanel(scene, *stage, profiler, ui, checkpoints.autosaveEvery());
      if (auto m = drawExportPanel(exports, *stage)) show(*m);
    }
    layout.see(ui.panelRight, ui.panelHeight);
    if (ui.showIndicators) {  // as the original's: apart from the panel (S hides only the panels)
      drawIndicators(counters, shown);
      if (shown.view) drawAxesGizmo(*shown.view);
    }

    if (ui.reloadRequested) {
      ui.reloadRequested = false;
      const auto result = shaders.reload();
      ui.messageIsError = !result.errors.empty();
      ui.message = result.errors.empty() ? "reloaded " + std::to_string(result.reloaded) + " programs"
                                         : result.errors.front() + "\n(kept the previous program)";
      for (const std::string& e : result.errors) log::error(e);
    }
    if (ui.resetRequested) {
      ui.resetRequested = false;
      ui.divergence.clear();
      if (exports.running()) show(exports.stop());  // the series ends where the run restarts
      stage->restart();
      frameNumber = 0;
    }
    if (ui.recoverRequested) {
      ui.recoverRequested = false;
      if (const std::optional<std::uint64_t> back = stage->recover()) {
        frameNumber -= std::min(*back, frameNumber);  // numbered as the good state's frame was
        ui.divergence.clear();
        ui.paused = false;
        ui.message = "resumed from the last good state with half the time step";
        ui.messageIsError = false;
      } else {
        ui.message = "no good state to go back to: reset (R) instead";
        ui.messageIsError = true;
      }
    }
    context.framebufferSize(fbw, fbh);
    const SceneArea area = sceneArea(fbw, ui.panelRight);  // right of the panel: it hides none of the scene
    stage->input(readInput(window, area, lastCursor, g_scroll, dt));
    for (const std::string& path : std::exchange(g_dropped, {})) {
      const std::string refused = stage->dropFile(path);
      ui.messageIsError = !refused.empty();
      ui.message = refused.empty() ? "dropped " + path : refused;
      if (!refused.empty()) log::error(refused);
    }

    if (area.width > 0 && fbh > 0) target.resize(area.width, fbh);
    const bool settling = job.maxFrames && frame >= *job.maxFrames;
    profiler.beginFrame();
    const bool stepOnce = ui.paused && ui.stepsPending > 0;  // one . press a frame
    ui.stepsPending = stepOnce ? ui.stepsPending - 1 : 0;
    const bool stepped = !settling && (!ui.paused || stepOnce);
    if (stepped) {
      stage->step(profiler);  // the model's frame, as `tidepool render` steps it, whatever the refresh rate
      ++frameNumber;
    }
    if (std::string t = windowTitle(scene.name, runningLabel(scene, *stage)); t != title)  // M, N: at the step
      glfwSetWindowTitle(window, (title = std::move(t)).c_str());
    stage->render(target, profiler);
    profiler.endFrame();
    if (auto m = exports.afterFrame(*stage, stepped)) show(*m);
    {
      const double metric = stage->liveMetric().second;
      ui.history.push(float(profiler.totalMs()), std::isfinite(metric) ? float(metric) : 0.0f, stage->probes());
    }
    if (const auto d = stage->divergence(); d && ui.divergence.empty()) {
      ui.divergence = d->message;
      log::error(d->message);
      ui.paused = true;  // say which method failed at which dt, and wait for the user
    }
    if (auto saved = checkpoints.afterFrame(*stage, frameNumber, std::exchange(ui.checkpointRequested, false))) {
      ui.message = saved->message;
      ui.messageIsError = saved->error;
    }

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbw, fbh);
    if (area.x > 0) {  // the panel's column
      glClearColor(0.06f, 0.06f, 0.06f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer().id());
    glBlitFramebuffer(0, 0, target.width(), target.height(), area.x, 0, area.x + area.width, fbh, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbw, fbh);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    const bool last = job.maxFrames && frame + 1 >= *job.maxFrames &&
                      (job.screenshot.empty() || (layout.settled() && ImGui::GetFrameCount() >= 3) ||
                       frame + 1 >= *job.maxFrames + kMaxSettleFrames);
    if (ui.screenshotRequested || (last && !job.screenshot.empty())) {
      ui.screenshotRequested = false;
      const std::filesystem::path path =
          last && !job.screenshot.empty() ? job.screenshot : std::filesystem::path(timestampedName());
      try {
        io::writePng(path, readWindow(fbw, fbh));
        ui.message = "saved " + path.string();
        ui.messageIsError = false;
        log::info(ui.message);
      } catch (const Error& e) {
        ui.message = e.what();
        ui.messageIsError = true;
        if (last) throw;
      }
    }
    context.swapBuffers();
    pacer.frameSubmitted();
    if (last) break;
  }

  if (exports.running()) exports.stop();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace tidepool
