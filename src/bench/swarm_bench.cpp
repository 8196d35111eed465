// `tidepool bench swarm`: the swarm step in ms and GB/s (state bytes read + written per step
// over GPU time), next to the copy bandwidth of the same bytes (a compute-shader copy, gl::BufferOps) measured
// in the same run, and the time to draw all N particles as 1-px points at 1920x1080.
//
//   tidepool bench swarm --n 1M,4M,16M,20M --storage fp32,fp16 --integrator all --repeats 50
//
// The step is bandwidth bound (16 B read + 16 B written per particle in fp32, 8 + 8 in fp16),
// so "% copy" is the figure of merit: the target is >= 80% for fp32 at 16M particles.
#include <cstdio>
#include <functional>
#include <memory>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "gl/buffer_ops.h"
#include "gl/framebuffer.h"
#include "render/swarm_renderer.h"
#include "sim/swarm/swarm.h"

namespace tidepool::bench {
namespace {

struct SwarmBenchOptions {
  std::string sizes = "1M,4M,16M,20M";
  std::string storages = "fp32,fp16";
  std::string integrators = "symplectic_euler";
  std::string renderSize = "1920x1080";
  bool render = true;
};

std::vector<std::string> splitList(const std::string& text) {  // empty items are skipped
  std::vector<std::string> out = splitCommas(text);
  std::erase(out, std::string());
  return out;
}

template <std::size_t N>
int indexOf(const std::array<const char*, N>& names, const std::string& name, const char* what) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return int(i);
  std::string all;
  for (const char* n : names) all += (all.empty() ? "" : ", ") + std::string(n);
  throw Error(std::string(what) + " '" + name + "' is not one of: " + all);
}

constexpr int kSettleSteps = 240;  // 2 s of the orbit preset before drawing

std::string countText(std::size_t n) {
  if (n % (1 << 20) == 0) return std::to_string(n >> 20) + "M";
  if (n % (1 << 10) == 0) return std::to_string(n >> 10) + "k";
  return std::to_string(n);
}

// Times too short to mean anything are shown as "-".
std::string gbPerS(double bytes, double ms) { return ms > 1e-3 ? fixed(bytes / (ms * 1e6), 1) : "-"; }
std::string percent(double copyMs, double stepMs) {
  return copyMs > 1e-3 && stepMs > 1e-3 ? fixed(100.0 * copyMs / stepMs, 1) : "-";
}

int runSwarmBench(Env& env, const SwarmBenchOptions& o) {
  std::vector<sim::Integrator> integrators;
  for (const std::string& name :
       splitList(o.integrators == "all" ? "explicit_euler,symplectic_euler,verlet,rk4" : o.integrators))
    integrators.push_back(sim::Integrator(indexOf(sim::kIntegratorNames, name, "--integrator")));
  std::vector<sim::Storage> storages;
  for (const std::string& name : splitList(o.storages))
    storages.push_back(sim::Storage(indexOf(sim::kStorageNames, name, "--storage")));
  int width = 0, height = 0;
  if (std::sscanf(o.renderSize.c_str(), "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0)
    throw Error("--render-size '" + o.renderSize + "' is not WIDTHxHEIGHT, e.g. 1920x1080");

  std::printf("swarm step on %s: medians of %d repeats (%d warm-up)\n", env.device.c_str(), env.common.repeats,
              env.common.warmup);
  std::printf(
      "points: all N drawn at %s after %d steps of the orbit preset (a clustered swarm, as on screen);\n"
      "  compute = atomic splat + resolve (the default for 1-px points), raster = GL_POINTS, additive\n",
      o.renderSize.c_str(), kSettleSteps);
  Table table({"n", "storage", "integrator", "ms/step", "GB/s", "copy ms", "copy GB/s", "% copy", "points compute ms",
               "points raster ms"});
  RenderTarget target(width, height);
  gl::GpuProfiler idle;  // never in a frame: the renderer's scopes stay silent under our queries
  Steps steps("bench swarm", int(parseSizes(o.sizes).size() * storages.size()));
  for (std::size_t n : parseSizes(o.sizes)) {
    for (sim::Storage storage : storages) {
      const std::string storageName = sim::kStorageNames[std::size_t(storage)];
      steps.begin(countText(n) + " particles, " + storageName);
      sim::SwarmParams params;
      params.particles = int(std::min<std::size_t>(n, std::size_t(1) << 30));
      params.storage = storage;
      std::unique_ptr<sim::Swarm> swarm;
      gl::Buffer scratch;
      try {
        sim::checkSwarmFits(n, storage, sim::swarmBytesPerParticle(storage));  // + the copy's scratch buffer
        swarm = std::make_unique<sim::Swarm>(env.shaders, params);
        scratch = gl::Buffer(swarm->stateBytes());
      } catch (const Error& e) {
        std::printf("skipped n=%s %s: %s\n", countText(n).c_str(), storageName.c_str(), e.what());
        continue;
      }
      swarm->setAspect(double(width) / height);
      const double bytes = 2.0 * double(swarm->stateBytes());  // read + written once per step
      const gl::BufferOps ops(env.shaders);
      const double copyMs = gpuMedianMs(env.common, [&] { ops.copy(swarm->state(), scratch, swarm->stateBytes()); });
      std::string computeMs = "-", rasterMs = "-";
      if (o.render) {
        for (int i = 0; i < kSettleSteps; ++i) swarm->step(1.0 / 120.0);
        SwarmRenderer renderer(env.shaders);
        SwarmViewParams view;
        view.showAttractors = false;
        auto draw = [&] { renderer.render(*swarm, view, {1, 1, 1}, {}, target, idle); };
        computeMs = fixed(gpuMedianMs(env.common, draw), 4);
        view.computePoints = false;
        rasterMs = fixed(gpuMedianMs(env.common, draw), 4);
      }
      for (sim::Integrator integrator : integrators) {
        swarm->params().integrator = integrator;
        swarm->reset();
        const double stepMs = gpuMedianMs(env.common, [&] { swarm->step(1.0 / 120.0); });
        table.add({countText(n), storageName, sim::kIntegratorNames[std::size_t(integrator)], fixed(stepMs, 4),
                   gbPerS(bytes, stepMs), fixed(copyMs, 4), gbPerS(bytes, copyMs), percent(copyMs, stepMs), computeMs,
                   rasterMs});
      }
    }
  }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addSwarmBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("swarm", "swarm step ms and GB/s against copy bandwidth; N points drawn at 1080p");
  auto o = std::make_shared<SwarmBenchOptions>();
  sub->add_option("--n", o->sizes, "particle counts, e.g. 1M,4M,16M,20M or 2^20..2^24")->capture_default_str();
  sub->add_option("--storage", o->storages, "fp32,fp16")->capture_default_str();
  sub->add_option("--integrator", o->integrators, "explicit_euler,symplectic_euler,verlet,rk4 or all")
      ->capture_default_str();
  sub->add_option("--render-size", o->renderSize, "target of the points draw, WIDTHxHEIGHT")->capture_default_str();
  sub->add_flag("!--no-render", o->render, "skip the points draw");
  return {sub, [o](Env& env) { return runSwarmBench(env, *o); }};
}

}  // namespace tidepool::bench
