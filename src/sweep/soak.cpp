#include "sweep/soak.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "base/progress.h"
#include "render/target.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "sim/life/life.h"
#include "sim/ripples/ripples.h"
#include "sim/swarm/swarm.h"

namespace tidepool::sweep {
namespace {

// One reading of a model's state: its size, how much of it is still sound, and its energy.
struct Reading {
  std::size_t count = 0, held = 0;
  double energy = 0;
};

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// Balls and fluid reduce on the GPU (their stats()); the others are read back and summed here,
// which is cheap at the sizes a soak runs.
Reading read(sim::Model& model, std::string& energyName) {
  if (auto* b = dynamic_cast<balls::Balls*>(&model)) {
    const balls::Stats s = b->stats();
    energyName = "kinetic + potential per unit mass (m^2/s^2)";
    return {s.count, s.count - std::min(s.count, s.nonFinite + s.outside), s.kinetic + s.potential};
  }
  if (auto* f = dynamic_cast<fluid::Fluid*>(&model)) {
    const fluid::Stats s = f->stats();
    energyName = "kinetic + potential (J)";
    return {s.count, s.count - std::min(s.count, s.nonFinite + s.outside), s.kinetic + s.potential};
  }
  Reading r;
  if (auto* l = dynamic_cast<life::Life*>(&model)) {
    energyName = "kinetic, sum of |v|^2/2 (world units^2/s^2)";
    const std::vector<glm::vec4> pos = l->downloadPositions(), vel = l->downloadVelocities();
    const glm::vec2 half = 0.5f * l->rules().size * 1.001f;  // the box [-w/2, w/2] x [-h/2, h/2]
    r.count = pos.size();
    for (std::size_t i = 0; i < pos.size(); ++i) {
      const glm::vec2 p(pos[i]), v(vel[i]);
      if (finite(p) && finite(v) && std::abs(p.x) <= half.x && std::abs(p.y) <= half.y) ++r.held;
      r.energy += 0.5 * double(glm::dot(v, v));
    }
    return r;
  }
  if (auto* w = dynamic_cast<sim::Swarm*>(&model)) {
    energyName = "kinetic, sum of |v|^2/2 (world units^2/s^2)";
    const bool walls = w->params().bounce;  // the image border, NDC [-1, 1]
    for (const sim::SwarmParticle& p : w->download()) {
      ++r.count;
      if (finite(p.pos) && finite(p.vel) && (!walls || (std::abs(p.pos.x) <= 1.0f && std::abs(p.pos.y) <= 1.0f)))
        ++r.held;
      r.energy += 0.5 * double(glm::dot(p.vel, p.vel));
    }
    return r;
  }
  if (auto* rp = dynamic_cast<ripples::Ripples*>(&model)) {
    // The wave equation's energy, (1/2) sum (v^2 + c^2 |grad h|^2) dx^2, with forward differences.
    energyName = "wave energy, sum of (v^2 + c^2 |grad h|^2) dx^2 / 2 (m^4/s^2)";
    const ripples::Params& p = rp->params();
    const std::vector<float> hv = rp->download();  // (h, v) per cell, rows of width
    const int width = p.width, height = int(hv.size() / 2 / std::size_t(std::max(width, 1)));
    const double c2 = double(p.waveSpeed) * p.waveSpeed, area = double(p.cellSize) * p.cellSize;
    auto h = [&](int x, int y) { return double(hv[2 * (std::size_t(y) * width + x)]); };
    r.count = rp->count();
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const double hc = h(x, y), v = hv[2 * (std::size_t(y) * width + x) + 1];
        if (!std::isfinite(hc) || !std::isfinite(v)) continue;
        ++r.held;
        const double gx = x + 1 < width ? h(x + 1, y) - hc : 0, gy = y + 1 < height ? h(x, y + 1) - hc : 0;
        r.energy += 0.5 * (v * v * area + c2 * (gx * gx + gy * gy));  // |grad h|^2 dx^2 = (dh)^2
      }
    return r;
  }
  throw Error("soak reads the balls, fluid, life, swarm and ripples models; this scene has none of them");
}

}  // namespace

double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

SoakResult soak(const Scene& scene, gl::ShaderLibrary& shaders, const SoakRun& run,
                const std::function<void(const SoakSample&)>& onSample) {
  if (run.steps < 1) throw Error("soak: --steps must be at least 1");
  const long every = run.every > 0 ? run.every : std::max(1L, run.steps / 20);
  auto stage = createStage(scene, shaders);
  if (!stage->model())
    throw Error("soak: '" + scene.name + "' is a " + scene.model + " scene, which has no model to soak");
  RenderTarget target(run.renderWidth, run.renderHeight);
  gl::GpuProfiler profiler;
  const auto start = std::chrono::steady_clock::now();
  SoakResult result;
  Progress progress("soak " + scene.name, int(std::min<long>(run.steps, 1L << 30)), true, "steps");

  for (long step = 0;; ++step) {
    if (step % every == 0 || step == run.steps) {
      profiler.beginFrame();
      stage->render(target, profiler);  // the view reads the same state, so that it soaks too
      profiler.endFrame();
      const Reading r = read(*stage->model(), result.energyName);
      SoakSample s;
      s.step = step;
      s.time = stage->simTime();
      s.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      s.rssMiB = residentMiB();
      s.count = r.count;
      s.held = r.held;
      s.energy = r.energy;
      result.samples.push_back(s);
      if (onSample) onSample(s);
    }
    if (step == run.steps) break;
    progress.update(int(std::min<long>(step, 1L << 30)));
    profiler.beginFrame();
    stage->step(profiler);
    profiler.endFrame();
    if (const auto d = stage->divergence())
      throw Error("soak: " + scene.name + " at step " + std::to_string(step + 1) + ": " + d->message);
  }
  progress.update(int(std::min<long>(run.steps, 1L << 30)));
  progress.finish();
  stage->flushChecks();
  if (const auto d = stage->divergence()) throw Error("soak: " + scene.name + " at the end: " + d->message);
  return result;
}

std::vector<std::string> judgeSoak(const std::vector<SoakSample>& samples, const SoakLimits& limits) {
  std::vector<std::string> failures;
  if (samples.size() < 2) return {"fewer than two samples: nothing to judge (more --steps or a smaller --every)"};
  char line[300];
  const long warmupEnd = std::lround(limits.warmup * double(samples.back().step));
  const SoakSample* settled = nullptr;  // the first sample after the warm-up
  double warmupEnergy = 0;
  for (const SoakSample& s : samples) {
    if (!settled && s.step >= warmupEnd && &s != &samples.back()) settled = &s;
    if ((!settled || settled == &s) && std::isfinite(s.energy)) warmupEnergy = std::max(warmupEnergy, s.energy);
  }
  // Memory: from the first sample after warm-up to the last.
  if (settled) {
    const double growth = samples.back().rssMiB - settled->rssMiB;
    if (growth > limits.rssGrowthMiB) {
      std::snprintf(line, sizeof line,
                    "RSS grew by %.1f MiB from step %ld to %ld (%.1f -> %.1f MiB), more than %.1f MiB", growth,
                    settled->step, samples.back().step, settled->rssMiB, samples.back().rssMiB, limits.rssGrowthMiB);
      failures.push_back(line);
    }
  }
  const double bound = limits.energyFactor * warmupEnergy;
  if (!(warmupEnergy > 0))
    failures.push_back("energy stayed 0 through the warm-up: nothing moves, so there is no bound to check against");
  for (const SoakSample& s : samples) {
    if (s.count != samples.front().count || s.held != s.count) {
      std::snprintf(line, sizeof line,
                    "count did not hold at step %ld: %zu of %zu sound (finite, inside), %zu at the start", s.step,
                    s.held, s.count, samples.front().count);
      failures.push_back(line);
      break;
    }
  }
  for (const SoakSample& s : samples) {
    if (!std::isfinite(s.energy) || (warmupEnergy > 0 && s.energy > bound)) {
      std::snprintf(line, sizeof line, "energy %.4g at step %ld, beyond %.4g (%.3g x the warm-up's largest, %.4g)",
                    s.energy, s.step, bound, limits.energyFactor, warmupEnergy);
      failures.push_back(line);
      break;
    }
  }
  return failures;
}

}  // namespace tidepool::sweep
