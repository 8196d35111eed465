// Study of particle life's storage precision: fp16 (packHalf2x16) against fp32 state. Both
// start from the same settled state and run T simulated seconds beside a double-precision CPU
// run (sim/life/measure/life_cpu.h); the error is the RMS distance between the GPU and CPU positions of
// each particle (minimum image on the torus), the cost the GPU time of a step divided by dt.
#include <cmath>
#include <cstdio>

#include "bench/bench.h"
#include "sim/life/life.h"
#include "sim/life/measure/life_cpu.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

constexpr float kDt = 0.025f;  // the article's step

// The article's defaults (8 species, friction 10) at its density, 65536 particles in 1024 x 576,
// with looping borders.
life::Rules rulesFor(std::size_t n) {
  const float scale = float(std::sqrt(double(n) / 65536.0));
  return life::generateRules({.species = 8,
                              .particleCount = int(n),
                              .size = {1024.0f * scale, 576.0f * scale},
                              .loopingBorders = true,
                              .seed = 1});
}

struct Deviation {
  double rms = 0, max = 0;  // world units
};

Deviation deviation(const life::Rules& rules, const life::Life& model, const std::vector<life::CpuParticle>& ref) {
  const std::vector<std::uint32_t> ids = model.ids();
  const std::vector<glm::vec4> pos = model.downloadPositions();
  Deviation d;
  for (std::size_t k = 0; k < pos.size(); ++k) {
    const double gap = glm::length(life::cpuBoxDelta(rules, ref[ids[k]].pos, glm::dvec2(pos[k])));
    d.rms += gap * gap;
    d.max = std::isfinite(gap) ? std::max(d.max, gap) : INFINITY;
  }
  d.rms = std::sqrt(d.rms / double(pos.size()));
  return d;
}

life::Params paramsFor(life::Storage storage) {
  life::Params p;
  p.storage = storage;
  p.maxDt = kDt;
  return p;
}

// GPU ms of one step from the given state (without id tracking: what a run costs).
double msPerStep(gl::ShaderLibrary& shaders, const life::Rules& rules, life::Storage storage,
                 const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  life::Life model(shaders, rules, paramsFor(storage));
  model.upload(pos, vel);
  const bench::Common timing{"auto", "", 10, 3};
  return bench::gpuMedianMs(timing, [&] { model.stepOnce(kDt); });
}

Result precision(Env& env) {
  const int settle = env.quick ? 20 : 100, steps = env.quick ? 10 : 40;
  const double seconds = steps * double(kDt);
  char title[200];
  std::snprintf(title, sizeof title,
                "life-precision: fp16 against fp32 state, position error after %.2g s against cost (one point per N)",
                seconds);
  Result r = emptyResult(
      "life", {"particles", "sim_seconds", "rms_position_error", "max_position_error", "rms_error_over_max_radius"},
      {.title = title,
       .xLabel = "GPU ms per simulated second (article defaults, looping, dt = 0.025 s)",
       .yLabel = "RMS position error vs a double-precision run (world units)"});
  const std::vector<std::size_t> sizes =
      env.quick ? std::vector<std::size_t>{1024, 4096} : std::vector<std::size_t>{16384, 65536, 262144, 1048576};
  for (std::size_t n : sizes) {
    const life::Rules rules = rulesFor(n);
    std::vector<glm::vec4> pos, vel;
    {
      life::Life start(env.shaders, rules, paramsFor(life::Storage::Fp32));
      for (int k = 0; k < settle; ++k) start.stepOnce(kDt);  // clusters form: the state the article shows
      pos = start.downloadPositions();
      vel = start.downloadVelocities();
    }
    std::vector<life::CpuParticle> ref = life::cpuState(pos, vel);
    for (int k = 0; k < steps; ++k) life::cpuStepEuler(rules, ref, kDt);
    for (life::Storage storage : {life::Storage::Fp32, life::Storage::Fp16}) {
      Deviation d;
      {
        life::Life model(env.shaders, rules, paramsFor(storage));
        model.upload(pos, vel);  // fp16 rounds the start: part of what it costs in accuracy
        model.trackIds(true);
        for (int k = 0; k < steps; ++k) model.stepOnce(kDt);
        d = deviation(rules, model, ref);
      }
      Row row;
      row.method = life::kStorageNames[int(storage)];
      row.dt = kDt;
      row.resolution = "N = " + std::to_string(n);
      row.costMsPerSimS = msPerStep(env.shaders, rules, storage, pos, vel) / kDt;
      row.metrics = {double(n), seconds, d.rms, d.max, d.rms / double(rules.maxRadius())};
      row.stable = std::isfinite(d.rms);
      addCostRow(r, row, d.rms);
      std::printf("  N = %zu %s: rms %.3g, max %.3g world units, %.4g ms per simulated s\n", n, row.method.c_str(),
                  d.rms, d.max, row.costMsPerSimS);
    }
  }
  return r;
}

}  // namespace

Study lifePrecisionStudy() {
  return {"life-precision", "fp16 vs fp32 state: position error after 1 s vs cost, per N", precision};
}

}  // namespace tidepool::sweep
