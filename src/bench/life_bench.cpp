// `tidepool bench life --n 65536..4194304`: particle life with the article's defaults (8 species,
// friction 10, walls, dt 0.025) at the article's density — the box scales with N so that
// 65536 particles fill 1024 x 576. After --settle steps (clusters form, which is what makes the
// neighbour search expensive), it reports ms per step and per pass (grid sort = count + scan +
// reorder, forces, integrate = step - sort - forces), steps/s, and candidate pairs: pairs the
// force pass examines in the visited cells (at most the 3x3 block, per species only the cells
// within its largest radius), per particle and per second of the force pass; "3x3 pairs/s" counts
// every pair of the 3x3 blocks (the measure) over the same force-pass time.
// A second table times the forces alone against a brute force over all N^2 pairs tiled
// through shared memory (shaders/life/forces_brute.comp), and reports the crossover N.
#include <cmath>
#include <cstdio>

#include "base/progress.h"
#include "bench/bench.h"
#include "gl/buffer_ops.h"
#include "life/bindings.glsl"
#include "sim/life/life.h"

namespace tidepool::bench {
namespace {

struct LifeOptions {
  std::string sizes = "65536..4194304";
  std::string brute = "256..262144";  // sizes for the brute-force crossover ("none": skip)
  int species = 8;
  int seed = 1;
  int settle = 100;  // steps before timing
  bool looping = false;
  std::string deterministic = "on";  // stable grid order: "on", "off" or "on,off" (one row each)
};

life::Rules rulesFor(const LifeOptions& o, std::size_t n) {
  const float scale = float(std::sqrt(double(n) / 65536.0));
  return life::generateRules({.species = o.species,
                              .particleCount = int(n),
                              .size = {1024.0f * scale, 576.0f * scale},
                              .loopingBorders = o.looping,
                              .seed = std::uint32_t(o.seed)});
}

void bruteForce(gl::ShaderLibrary& shaders, const life::Life& model) {
  const gl::Kernel<life::PairUniforms> brute(
      shaders, "life/forces_brute.comp", {LIFE_POSITIONS, LIFE_ACCELERATIONS, LIFE_FORCE_TABLE},
      model.rules().loopingBorders ? std::vector<gl::ShaderDefine>{{"LOOPING", "1"}} : std::vector<gl::ShaderDefine>{});
  model.positions().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  model.accelerations().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_ACCELERATIONS);
  model.forceTable().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_FORCE_TABLE);
  brute.dispatchThreads(model.count(), model.pairUniforms());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Pairs in the full 3x3 block of cells around each particle's cell (clamped at walls, wrapped
// when looping): the measure, an upper bound of what forces.comp examines.
double blockPairs(const gl::BufferOps& ops, const life::Life& model) {
  const glm::uvec3 dims = model.grid().dims();
  const std::vector<GLuint> count = ops.readBack<GLuint>(model.grid().cellCount(), model.grid().cells());
  const bool wrap = model.rules().loopingBorders;
  double total = 0;
  for (int y = 0; y < int(dims.y); ++y)
    for (int x = 0; x < int(dims.x); ++x) {
      double block = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int cx = x + dx, cy = y + dy;
          if (wrap) {
            cx = (cx + int(dims.x)) % int(dims.x);
            cy = (cy + int(dims.y)) % int(dims.y);
          } else if (cx < 0 || cy < 0 || cx >= int(dims.x) || cy >= int(dims.y)) {
            continue;
          }
          block += count[std::size_t(cy) * dims.x + std::size_t(cx)];
        }
      total += double(count[std::size_t(y) * dims.x + std::size_t(x)]) * block;
    }
  return total;
}

void settle(life::Life& model, int steps) {
  for (int i = 0; i < steps; ++i) model.stepOnce(model.params().maxDt);
  glFinish();
}

int run(Env& env, const LifeOptions& o) {
  std::printf(
      "life benchmark on %s (%d species, seed %d, %s, dt 0.025, density 65536 per 1024x576, %d settle "
      "steps, medians of %d)\n",
      env.device.c_str(), o.species, o.seed, o.looping ? "looping" : "walls", o.settle, env.common.repeats);
  const gl::BufferOps ops(env.shaders);  // read-backs that leave the model's buffers where they are
  Table table({"N", "determ.", "box", "grid", "pairs/particle", "ms/step", "steps/s", "sort ms", "forces ms",
               "integrate ms", "pairs/s", "3x3 pairs/s"});
  Steps steps("bench life", int(parseSizes(o.sizes).size() * parseOnOff(o.deterministic, "--deterministic").size()));
  for (std::size_t n : parseSizes(o.sizes))
    for (bool stable : parseOnOff(o.deterministic, "--deterministic")) {
      steps.begin(std::to_string(n) + " particles, determ. " + (stable ? "on" : "off"));
      life::Params params;
      params.deterministic = stable;
      life::Life model(env.shaders, rulesFor(o, n), params);
      settle(model, o.settle);
      const float dt = model.params().maxDt;
      const double stepMs = gpuMedianMs(env.common, [&] { model.stepOnce(dt); });
      const double sortMs = gpuMedianMs(env.common, [&] { model.sortByCell(); });
      const double forcesMs = gpuMedianMs(env.common, [&] { model.evaluateForces(); });
      const double pairs = double(model.countCandidatePairs());
      const double block = blockPairs(ops, model);  // the counts of the last sort, i.e. these positions
      const glm::uvec3 dims = model.grid().dims();
      char box[64], grid[64], rate[32], blockRate[32];
      std::snprintf(box, sizeof box, "%.0fx%.0f", double(model.rules().size.x), double(model.rules().size.y));
      std::snprintf(grid, sizeof grid, "%ux%u", dims.x, dims.y);
      std::snprintf(rate, sizeof rate, "%.3g", pairs / (forcesMs * 1e-3));
      std::snprintf(blockRate, sizeof blockRate, "%.3g", block / (forcesMs * 1e-3));
      table.add({std::to_string(n), stable ? "on" : "off", box, grid, fixed(pairs / double(n), 1), fixed(stepMs, 4),
                 fixed(1000.0 / stepMs, 1), fixed(sortMs, 4), fixed(forcesMs, 4),
                 fixed(std::max(0.0, stepMs - sortMs - forcesMs), 4), rate, blockRate});
    }
  steps.finish();
  table.print();
  if (o.brute != "none") {
    Steps bruteSteps("bench life brute force", int(parseSizes(o.brute).size()));
    std::printf("\nforces: grid (sort + force pass) against the shared-memory-tiled N^2 brute force\n");
    Table cross({"N", "grid sort+forces ms", "brute ms", "brute/grid", "max |diff| / |F|"});
    std::size_t crossover = 0;
    for (std::size_t n : parseSizes(o.brute)) {
      bruteSteps.begin(std::to_string(n) + " particles");
      life::Life model(env.shaders, rulesFor(o, n));
      settle(model, o.settle);
      const double gridMs = gpuMedianMs(env.common, [&] { model.computeForces(); });
      // Same positions for both: compare the two results once.
      model.computeForces();
      const std::vector<glm::vec2> binned = ops.readBack<glm::vec2>(model.accelerations(), n);
      const double bruteMs = gpuMedianMs(env.common, [&] { bruteForce(env.shaders, model); });
      const std::vector<glm::vec2> brute = ops.readBack<glm::vec2>(model.accelerations(), n);
      double worst = 0, scale = 0;
      for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, double(glm::length(binned[i] - brute[i])));
        scale = std::max(scale, double(glm::length(brute[i])));
      }
      if (!crossover && gridMs < bruteMs) crossover = n;
      char diff[32];
      std::snprintf(diff, sizeof diff, "%.2g", worst / std::max(scale, 1e-30));
      cross.add({std::to_string(n), fixed(gridMs, 4), fixed(bruteMs, 4), fixed(bruteMs / gridMs, 2), diff});
    }
    cross.print();
    if (crossover)
      std::printf("crossover: the grid is faster from N = %zu (of the sizes measured)\n", crossover);
    else
      std::printf("crossover: the brute force was faster at every size measured\n");
  }
  return finishPrinted(env, table);
}

}  // namespace

Benchmark addLifeBench(CLI::App& bench) {
  auto* sub =
      bench.add_subcommand("life", "particle life: ms per step and pass, candidate pairs/s, brute-force crossover");
  auto o = std::make_shared<LifeOptions>();
  sub->add_option("--n", o->sizes, "particle counts, e.g. 65536..4194304 or 2^16,2^20");
  sub->add_option("--brute", o->brute, "sizes for the brute-force crossover table, or none");
  sub->add_option("--species", o->species, "species (1-20)")->check(CLI::Range(1, 20));
  sub->add_option("--seed", o->seed, "rule seed")->check(CLI::Range(0, 2147483647));
  sub->add_option("--settle", o->settle, "steps run before timing (clusters form)")->check(CLI::Range(0, 100000));
  sub->add_flag("--looping", o->looping, "looping borders instead of walls");
  sub->add_option("--deterministic", o->deterministic,
                  "stable grid order (bit-identical runs) on or off, one row each, e.g. on,off");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
