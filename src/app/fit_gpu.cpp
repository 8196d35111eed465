#include "app/fit_gpu.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "base/log.h"
#include "gl/gl.h"
#include "gl/gpu_profiler.h"
#include "io/echo.h"
#include "render/target.h"
#include "scene/scene.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

io::Json atResolution(const io::Json& overrides, double resolution) {
  io::Json patch = overrides.is_object() ? overrides : io::Json::object();
  patch.merge_patch(io::Json{{"particles", {{"resolution", resolution}}}});
  return patch;
}

// The resolution the scene states (its file's, or the overrides'): where the search starts.
double statedResolution(const Scene& scene) {
  if (scene.params.holds<balls::Params>()) return scene.params.model<balls::Params>().resolution;
  if (scene.params.holds<fluid::Params>()) return scene.params.model<fluid::Params>().resolution;
  throw Error("--fit-gpu refines water (balls or fluid scenes, particles.resolution); '" + io::printable(scene.name) +
              "' runs model " + scene.model);
}

FitTrial measure(const std::filesystem::path& file, const io::Json& overrides, gl::ShaderLibrary& shaders,
                 const FitOptions& o, double resolution) {
  FitTrial t;
  t.resolution = resolution;
  std::unique_ptr<Stage> stage;
  Scene scene;
  try {
    scene = loadScene(file, atResolution(overrides, resolution));
    stage = createStage(scene, shaders);
  } catch (const Error& e) {  // too many particles for the device, or substeps past the engine's limit
    t.refused = e.what();
    return t;
  }
  t.particles = stage->model() ? stage->model()->count() : 0;
  RenderTarget target(o.width, o.height);
  gl::GpuProfiler profiler;
  std::vector<double> ms;
  for (int i = 0; i < o.frames + 2; ++i) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    profiler.beginFrame();
    stage->step(profiler);
    stage->render(target, profiler);
    profiler.endFrame();
    glFinish();
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    if (i >= 2) ms.push_back(took.count());           // two warm-up frames: programs compiled, caches filled
    if (i >= 1 && took.count() > 4.0 * o.budgetMs) {  // far over already: not worth more frames
      ms.assign(1, took.count());
      break;
    }
  }
  std::sort(ms.begin(), ms.end());
  t.frameMs = ms[ms.size() / 2];
  t.fits = t.frameMs <= o.budgetMs;
  return t;
}

}  // namespace

FitResult fitResolution(const std::filesystem::path& file, const io::Json& overrides, gl::ShaderLibrary& shaders,
                        const FitOptions& o) {
  const double lowest = 0.05;  // particles.resolution's own range
  const double highest = std::clamp(o.maxResolution, lowest, 64.0);
  FitResult fit;
  double r = std::clamp(statedResolution(loadScene(file, overrides)), lowest, highest);
  double over = std::numeric_limits<double>::infinity();  // the coarsest that did not fit
  for (int trial = 0; trial < std::max(1, o.maxTrials); ++trial) {
    const FitTrial t = measure(file, overrides, shaders, o, r);
    fit.trials.push_back(t);
    double next = r;
    if (t.fits) {
      fit.resolution = std::max(fit.resolution, r);
      next = r * std::clamp(0.97 * std::pow(o.budgetMs / std::max(t.frameMs, 1e-3), 0.25), 1.05, 4.0);
    } else {
      over = std::min(over, r);
      next = t.refused.empty() ? r * std::clamp(0.97 * std::pow(o.budgetMs / t.frameMs, 0.25), 0.25, 0.95) : 0.7 * r;
    }
    next = std::clamp(next, lowest, highest);
    if (fit.resolution > 0 && std::isfinite(over)) {  // bracketed: bisect (geometrically) when the step leaves it
      if (over / fit.resolution < 1.08) break;
      if (next <= fit.resolution * 1.02 || next >= over / 1.02) next = std::sqrt(fit.resolution * over);
    }
    if (t.fits && r >= highest) break;  // as fine as allowed
    if (!t.fits && r <= lowest) break;  // as coarse as allowed, and still over
    if (std::abs(next / r - 1.0) < 0.02) break;
    r = next;
  }
  return fit;
}

std::string FitResult::table() const {
  std::string out = "resolution  particles   ms/frame  fits\n";
  for (const FitTrial& t : trials) {
    char line[256];
    if (t.refused.empty())
      std::snprintf(line, sizeof line, "%10s %10zu %10.2f  %s\n", number(t.resolution).c_str(), t.particles, t.frameMs,
                    t.fits ? "yes" : "no");
    else
      std::snprintf(line, sizeof line, "%10s    refused: %s\n", number(t.resolution).c_str(), t.refused.c_str());
    out += line;
  }
  return out;
}

io::Json withFittedResolution(const FitResult& fit, const io::Json& overrides, double budgetMs) {
  if (fit.resolution > 0) return atResolution(overrides, fit.resolution);
  const FitTrial* coarsest = nullptr;
  for (const FitTrial& t : fit.trials)
    if (t.refused.empty() && (!coarsest || t.resolution < coarsest->resolution)) coarsest = &t;
  if (!coarsest)
    throw Error("--fit-gpu: no resolution could be built on this device (" +
                (fit.trials.empty() ? std::string("none tried") : fit.trials.back().refused) + ")");
  throw Error("--fit-gpu: even resolution " + number(coarsest->resolution) + " takes " + number(coarsest->frameMs) +
              " ms per frame, over the budget of " + number(budgetMs) + " ms (raise --budget)");
}

io::Json fitOverrides(const std::filesystem::path& scene, const io::Json& overrides, gl::ShaderLibrary& shaders,
                      const FitOptions& options) {
  const FitResult fit = fitResolution(scene, overrides, shaders, options);
  log::info("fit to this GPU (step + render of a frame, budget " + number(options.budgetMs) + " ms):\n" + fit.table());
  return withFittedResolution(fit, overrides, options.budgetMs);
}

}  // namespace tidepool
