#include "cli/commands.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "app/headless.h"
#include "app/window_app.h"
#include "base/log.h"
#include "base/number_text.h"
#include "cli/scene_options.h"
#include "gl/context.h"
#include "gl/context_window.h"
#include "gl/info.h"
#include "gl/selftest.h"
#include "io/echo.h"
#include "io/json.h"
#include "scene/scene.h"

namespace tidepool::cli {
namespace {

const std::vector<std::string> kBackends = {"auto", "egl", "osmesa", "window"};

#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

void applyCheckpointOptions(const CheckpointOpts& o, RenderJob& job) {
  job.resume = o.resume;
  job.checkpoint = o.checkpoint;
  job.checkpointEvery = o.every;
}

// Where a clip goes when the command line names no folder: "<root>/<scene file's stem>".
std::filesystem::path defaultOutDir(const std::filesystem::path& sceneFile, const std::filesystem::path& root = "out") {
  return root / sceneFile.stem();
}

}  // namespace

void parseSize(const std::string& text, int& width, int& height) {
  // Up to five digits a side, as "1280x720": plain digits, no sign, space or exponent.
  const auto side = [](std::string_view s, int& out) {
    if (s.empty() || s.size() > 5 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return false;
    out = std::stoi(std::string(s));
    return out > 0;
  };
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  if (x == std::string::npos || !side(std::string_view(text).substr(0, x), w) ||
      !side(std::string_view(text).substr(x + 1), h))
    throw Error("--size '" + io::printable(text) + "' is not WIDTHxHEIGHT (e.g. 1280x720)");
  width = w;
  height = h;
}

namespace {

// The number CLI11 will read, or a message why it is not one that fits.
std::string finiteNumber(const std::string& text, double& v) {
  char* end = nullptr;
  v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return "'" + io::printable(text) + "' is not a number";
  if (!std::isfinite(v)) return io::printable(text) + " is not a finite number";
  return "";
}

}  // namespace

CLI::Validator finiteRange(double min, double max) {
  const std::string range = "[" + numberText(min) + ", " + numberText(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) {
        double v = 0;
        std::string why = finiteNumber(text, v);
        if (why.empty() && !(v >= min && v <= max)) why = numberText(v) + " is out of range " + range;
        return why;
      },
      "in " + range);
}

CLI::Validator finitePositive() {
  return CLI::Validator(
      [](std::string& text) {
        double v = 0;
        std::string why = finiteNumber(text, v);
        if (why.empty() && !(v > 0)) why = numberText(v) + " is not above 0";
        return why;
      },
      "above 0");
}

Command addInfo(CLI::App& app) {
  auto* sub = app.add_subcommand("info", "GL vendor, renderer, version and compute limits");
  auto backend = std::make_shared<std::string>("auto");
  sub->add_option("--backend", *backend, "headless context: auto (EGL, then OSMesa), egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  return {sub, [backend] {
            auto context = gl::createHeadlessContext({gl::parseBackend(*backend), false});
            std::printf("backend                   %s\n%s", context->description().c_str(),
                        gl::formatInfo(gl::queryInfo()).c_str());
            gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
            const std::string failure = gl::computeSelfTest(shaders);
            std::printf("compute self-test         %s\n", failure.empty() ? "ok" : ("FAILED: " + failure).c_str());
            return failure.empty() ? 0 : 1;
          }};
}

Command addRender(CLI::App& app) {
  auto* sub = app.add_subcommand("render", "render a scene headless to PNG frames and/or a video");
  struct Opts {
    RenderJob job;
    int frames = 0;
    std::string size, backend = "auto";
    bool quiet = false;
    std::string rules, exportFormat, surfaceFormat = "ply";
    SurfaceParams surface;
    CheckpointOpts checkpoints;
    ResolutionOpts resolution;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->job.scene, "scene file, or a name from assets/scenes (e.g. blank)")->required();
  sub->add_option("--frames", o->frames,
                  "number of frames (default: the scene's clip.frames); with --resume, frames after the checkpoint's")
      ->check(CLI::Range(1, 1000000));
  sub->add_option("--size", o->size, "image size WIDTHxHEIGHT (default: the scene's clip size)");
  sub->add_option("--out", o->job.outDir,
                  "folder for frame_00000.png ... (default, when there is no --video either: out/<scene>)");
  sub->add_option("--video", o->job.video, "video file written through ffmpeg (e.g. clip.mp4)");
  auto* exportOpt = sub->add_option("--export", o->exportFormat,
                                    "also write the particles to --out: vtk (frame_*.vtp + particles.pvd for "
                                    "ParaView) or ply (frame_*.ply for Blender); ripples: vtk, its heightfield; "
                                    "surface: the water's surface mesh (balls, fluid: surface_*.ply)");
  sub->add_option("--every", o->job.exportEvery, "with --export: every K-th frame (frame 0 included; default 1)")
      ->needs(exportOpt);
  sub->add_flag("--no-frames", o->job.noFrames, "with --export: no PNG frames in --out")->needs(exportOpt);
  sub->add_option("--surface-resolution", o->surface.resolution,
                  "with --export surface: grid cells along the domain's longest axis (default 128)")
      ->needs(exportOpt);
  sub->add_option("--surface-smoothing", o->surface.smoothing,
                  "with --export surface: the density kernel's reach in particle radii (default 4)")
      ->needs(exportOpt)
      ->check(finiteRange(1.0, 16.0));
  sub->add_option(
         "--surface-iso", o->surface.iso,
         "with --export surface: the level of the density (1 = water at rest) the surface passes (default 0.5)")
      ->needs(exportOpt)
      ->check(finiteRange(0.0, 1.0));
  sub->add_option("--surface-format", o->surfaceFormat,
                  "with --export surface: ply (default; x y z nx ny nz and faces), obj or vtk (+ surface.pvd)")
      ->needs(exportOpt);
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  sub->add_flag("--debug-gl", o->job.debugGl, "log KHR_debug driver messages");
  sub->add_flag("--quiet", o->quiet, "no progress: no particle count, time estimate or progress bar");
  sub->add_option("--rules", o->rules, "life: rules JSON file, preset name or share code (sets params.rules)");
  addCheckpointOptions(sub, o->checkpoints);
  addResolutionOptions(sub, o->resolution);
  return {sub, [o, sub] {
            const std::vector<ParamOverride> overrides = sceneOverrides(o->resolution, o->rules);
            checkSceneOptions(o->job.scene, overrides, o->resolution, o->checkpoints.resume);
            RenderJob job = o->job;
            if (job.outDir.empty() && job.video.empty()) {  // as `run` without a display: out/<scene>
              job.outDir = defaultOutDir(resolveScenePath(job.scene));
              log::info("no --out or --video: writing to " + io::shownPath(job.outDir));
            }
            applyCheckpointOptions(o->checkpoints, job);
            if (o->frames > 0) job.frames = o->frames;
            if (!o->size.empty()) {
              int w = 0, h = 0;
              parseSize(o->size, w, h);
              job.width = w;
              job.height = h;
            }
            job.backend = gl::parseBackend(o->backend);
            job.debugGl |= kDebugBuild;
            job.progress = !o->quiet;
            job.paramOverrides = merged(overrides);
            if (o->resolution.fit) job.fitBudgetMs = o->resolution.budgetMs;
            if (o->exportFormat == "surface") {
              job.surface = o->surface;
              job.exportFormat = io::parseSurfaceFormat(o->surfaceFormat);
            } else if (!o->exportFormat.empty()) {
              for (const char* option :
                   {"--surface-resolution", "--surface-smoothing", "--surface-iso", "--surface-format"})
                if (sub->count(option) > 0) throw Error(std::string(option) + " needs --export surface");
              job.exportFormat = io::parseExportFormat(o->exportFormat);
            }
            renderHeadless(job);
            return 0;
          }};
}

Command addRun(CLI::App& app) {
  auto* sub = app.add_subcommand("run", "open a scene in a window (headless clip when there is no display)");
  struct Opts {
    std::string scene = "default", size = "1280x720", backend = "auto", screenshot, out = "out", rules;
    int frames = 0;
    bool noVsync = false, debugGl = false;
    int framesInFlight = 2;
    CheckpointOpts checkpoints;
    ResolutionOpts resolution;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "scene file, or a name from assets/scenes (default: default)");
  auto* sizeOpt = sub->add_option(
      "--size", o->size,
      "window size WIDTHxHEIGHT (default 1280x720); without a display, the clip's (default: the scene's)");
  sub->add_option("--frames", o->frames, "close after N frames (0: run until closed)")->check(CLI::Range(0, 100000000));
  sub->add_option("--screenshot", o->screenshot,
                  "save the window to this PNG after the last frame (the run holds still until the panel is laid out)");
  sub->add_option("--backend", o->backend, "auto (window if there is a display), window, egl or osmesa")
      ->check(CLI::IsMember(kBackends));
  sub->add_option("--out", o->out, "folder for the headless clip when there is no display");
  sub->add_flag("--no-vsync", o->noVsync, "render as fast as possible");
  sub->add_option("--frames-in-flight", o->framesInFlight, "frames queued ahead of the GPU at most (window)")
      ->check(CLI::Range(1, 8));
  sub->add_option("--rules", o->rules, "life: rules JSON file, preset name or share code (sets params.rules)");
  sub->add_flag("--debug-gl", o->debugGl, "log KHR_debug driver messages");
  addCheckpointOptions(sub, o->checkpoints);
  addResolutionOptions(sub, o->resolution);
  return {sub, [o, sizeOpt] {
            int w = 0, h = 0;
            parseSize(o->size, w, h);
            const gl::Backend backend = gl::parseBackend(o->backend);
            const std::vector<ParamOverride> settings = sceneOverrides(o->resolution, o->rules);
            const Scene scene = checkSceneOptions(o->scene, settings, o->resolution, o->checkpoints.resume);
            const io::Json overrides = merged(settings);
            std::optional<double> fitBudgetMs;
            if (o->resolution.fit) fitBudgetMs = o->resolution.budgetMs;
            const bool window =
                backend == gl::Backend::Window || (backend == gl::Backend::Auto && gl::displayAvailable());
            if (window) {
              const bool debugGl = o->debugGl || kDebugBuild;
              WindowJob job{o->scene,
                            w,
                            h,
                            std::nullopt,
                            o->screenshot,
                            debugGl,
                            !o->noVsync,
                            overrides,
                            o->checkpoints.resume,
                            o->checkpoints.checkpoint,
                            o->checkpoints.every,
                            o->framesInFlight,
                            fitBudgetMs};
              if (o->frames > 0) job.maxFrames = o->frames;
              return runWindow(job);
            }
            // No display: render the scene's default clip headless and say where it went.
            RenderJob job;
            job.scene = o->scene;
            job.paramOverrides = overrides;
            job.fitBudgetMs = fitBudgetMs;
            job.outDir = defaultOutDir(scene.file, o->out);  // the scene loaded above
            if (o->frames > 0) job.frames = o->frames;
            if (sizeOpt->count() > 0) {  // else the scene's clip size, not the window's default
              job.width = w;
              job.height = h;
            }
            job.backend = backend;
            job.debugGl = o->debugGl || kDebugBuild;
            applyCheckpointOptions(o->checkpoints, job);
            log::info("no display: rendering '" + io::printable(scene.name) + "' headless");
            renderHeadless(job);
            return 0;
          }};
}

}  // namespace tidepool::cli
