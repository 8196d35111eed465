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

// --resume, --checkpoint and --checkpoint-every, alike for render and run.
struct CheckpointOpts {
  std::string resume, checkpoint;
  double every = 0;
};

void addCheckpointOptions(CLI::App* sub, CheckpointOpts& o) {
  sub->add_option("--resume", o.resume,
                  "start from this checkpoint (a file --checkpoint wrote) instead of t = 0; render numbers its "
                  "frames on after the checkpoint's");
  sub->add_option("--checkpoint", o.checkpoint,
                  "write checkpoints to this file (atomically; default: beside the output, e.g. out/dam.ckpt)");
  sub->add_option("--checkpoint-every", o.every,
                  "save a checkpoint every this many simulated seconds, and after the last frame")
      ->check(finitePositive());
}

void applyCheckpointOptions(const CheckpointOpts& o, RenderJob& job) {
  job.resume = o.resume;
  job.checkpoint = o.checkpoint;
  job.checkpointEvery = o.every;
}

// --resolution, --fit-gpu, --budget and --set, alike for render and run.
struct ResolutionOpts {
  double resolution = 0;  // 0: as the scene states
  bool fit = false;
  double budgetMs = 1000.0 / 30.0;
  std::vector<std::string> sets;  // KEY=VALUE
};

// Nesting of a JSON value: 0 for a number or string, 1 for [1, 2], 2 for {"a": [1]}. The value
// came through parseJson, so it is at most kMaxJsonDepth deep and the recursion is bounded.
int jsonDepth(const io::Json& value) {
  int deepest = 0;
  if (value.is_structured())
    for (const io::Json& child : value) deepest = std::max(deepest, jsonDepth(child));
  return value.is_structured() ? deepest + 1 : 0;
}

bool isName(std::string_view s) {
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  const auto letterOrDigit = [&](char c) { return letter(c) || std::isdigit(static_cast<unsigned char>(c)); };
  return !s.empty() && letter(s[0]) && std::all_of(s.begin() + 1, s.end(), letterOrDigit);
}

// --set view.mode=water: the value as JSON when it reads as JSON (3, true, [0,1,0]), else as text.
// Read in one pass, under the size and depth limits of a scene file: the dotted key's names count
// as levels of nesting, as they do in the object they become.
io::Json setOverride(const std::string& text) {
  const std::string shown = "--set '" + io::printable(text) + "'";
  if (text.size() > io::kMaxJsonFileBytes)
    throw Error(shown + ": " + io::byteSize(text.size()) + ", larger than the " + io::byteSize(io::kMaxJsonFileBytes) +
                " allowed for JSON");
  const std::size_t equals = text.find('=');
  std::vector<std::string> keys;
  for (std::size_t begin = 0; equals != std::string::npos && begin <= equals;) {
    const std::size_t dot = std::min(text.find('.', begin), equals);
    keys.push_back(text.substr(begin, dot - begin));
    if (!isName(keys.back()) || keys.size() > std::size_t(io::kMaxJsonDepth)) break;
    begin = dot + 1;
  }
  if (equals == std::string::npos || equals + 1 == text.size() || keys.empty() || !isName(keys.back()))
    throw Error(shown + " is not KEY=VALUE with a params key (e.g. view.mode=water)");
  if (keys.size() > std::size_t(io::kMaxJsonDepth))
    throw Error(shown + ": the key is nested deeper than the " + std::to_string(io::kMaxJsonDepth) +
                " levels a scene may nest");
  const std::string valueText = text.substr(equals + 1);
  io::Json patch;
  try {
    patch = io::parseJson(valueText, "--set");
  } catch (const Error&) {
    patch = valueText;
  }
  if (keys.size() + std::size_t(jsonDepth(patch)) > std::size_t(io::kMaxJsonDepth))
    throw Error(shown + ": the key and the value together are nested deeper than the " +
                std::to_string(io::kMaxJsonDepth) + " levels a scene may nest");
  for (auto key = keys.rbegin(); key != keys.rend(); ++key) {
    io::Json level = io::Json::object();
    level[*key] = std::move(patch);
    patch = std::move(level);
  }
  return patch;
}

// Where a clip goes when the command line names no folder: "<root>/<scene file's stem>".
std::filesystem::path defaultOutDir(const std::filesystem::path& sceneFile, const std::filesystem::path& root = "out") {
  return root / sceneFile.stem();
}

void addResolutionOptions(CLI::App* sub, ResolutionOpts& o) {
  sub->add_option("--resolution", o.resolution,
                  "water: refine the particle spacing R times, keeping the setup (counts x R^3, dt / R; "
                  "sets params.particles.resolution)")
      ->check(finiteRange(0.05, 64.0));
  sub->add_flag("--fit-gpu", o.fit, "water: the finest resolution whose frame (steps + render) fits --budget here");
  sub->add_option("--budget", o.budgetMs, "with --fit-gpu: ms per frame (default 33.3, 30 frames/s)")
      ->check(finiteRange(0.1, 1e6));
  sub->add_option("--set", o.sets, "set a scene parameter, KEY=VALUE (e.g. view.mode=water); repeatable");
}

// The scene overrides with --set and --resolution merged in; the budget when --fit-gpu is asked for.
io::Json applyResolutionOptions(const ResolutionOpts& o, io::Json overrides, std::optional<double>& fitBudgetMs) {
  if (!overrides.is_object()) overrides = io::Json::object();
  for (const std::string& set : o.sets) overrides.merge_patch(setOverride(set));
  if (o.resolution > 0) overrides.merge_patch(io::Json{{"particles", {{"resolution", o.resolution}}}});
  if (o.fit) fitBudgetMs = o.budgetMs;
  return overrides;
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

std::string compact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

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
  const std::string range = "[" + compact(min) + ", " + compact(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) {
        double v = 0;
        std::string why = finiteNumber(text, v);
        if (why.empty() && !(v >= min && v <= max)) why = compact(v) + " is out of range " + range;
        return why;
      },
      "in " + range);
}

CLI::Validator finitePositive() {
  return CLI::Validator(
      [](std::string& text) {
        double v = 0;
        std::string why = finiteNumber(text, v);
        if (why.empty() && !(v > 0)) why = compact(v) + " is not above 0";
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
            if (!o->rules.empty()) job.paramOverrides = {{"rules", o->rules}};
            job.paramOverrides = applyResolutionOptions(o->resolution, job.paramOverrides, job.fitBudgetMs);
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
  sub->add_option("--size", o->size, "window size WIDTHxHEIGHT");
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
  return {sub, [o] {
            int w = 0, h = 0;
            parseSize(o->size, w, h);
            const gl::Backend backend = gl::parseBackend(o->backend);
            std::optional<double> fitBudgetMs;
            const io::Json overrides = applyResolutionOptions(
                o->resolution, o->rules.empty() ? io::Json() : io::Json{{"rules", o->rules}}, fitBudgetMs);
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
            const Scene scene = loadScene(resolveScenePath(o->scene));
            job.outDir = defaultOutDir(scene.file, o->out);  // the scene loaded above
            if (o->frames > 0) job.frames = o->frames;
            job.backend = backend;
            job.debugGl = o->debugGl || kDebugBuild;
            applyCheckpointOptions(o->checkpoints, job);
            log::info("no display: rendering '" + io::printable(scene.name) + "' headless");
            renderHeadless(job);
            return 0;
          }};
}

}  // namespace tidepool::cli
