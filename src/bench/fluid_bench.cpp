// `tidepool bench fluid <scene> --n 65536,1M --iterations 4 --loads off,on --bodies 0,10 --steps 10:110`: median
// GPU ms per fluid step over a window of steps, split by pass (the solver's λ and Δp passes summed
// over the iterations), with steps per second and GPU bytes per particle. --n sets the particle
// count of a block-filled scene (bench-fluid) by choosing the spacing that fills the block with
// that many particles on the cubic lattice; other scenes run as they are. --loads on adds force
// probes on the floor and on every obstacle (sim/water/boundary_loads.h: what measuring costs);
// --bodies N adds N boxes afloat at the block's surface, dynamic (sim/water/bodies.h) or, with
// --dynamic off, held where they are: what moving them costs beyond their boundary particles.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "bench/water_rows.h"
#include "io/echo.h"
#include "scene/fluid_stage.h"
#include "sim/fluid/fluid.h"

namespace tidepool::bench {
namespace {

// The spacing that fills the scene's block with about n particles (one per d³).
float spacingFor(const fluid::Params& p, std::size_t n) {
  const water::Setup& w = p;
  const glm::vec3 extent = glm::max(glm::min(w.fillMax, w.domainMax) - glm::max(w.fillMin, w.domainMin), 0.0f);
  return float(std::cbrt(double(extent.x) * extent.y * extent.z / double(n)));
}

int run(Env& env, const std::string& sceneName, const std::string& sizes, const std::string& iterations,
        const std::string& deterministic, const std::string& loads, const std::string& bodiesText,
        const std::string& dynamic, const std::string& window) {
  const Scene scene = loadScene(resolveScenePath(sceneName));
  const fluid::Params base = fluidScene(scene).model;
  const StepWindow w = parseStepWindow(window);
  const bool block = base.fill == water::Fill::Block;
  const std::vector<int> iterationCounts = parseWholeNumbers(iterations, "--iterations", 1, 100);
  const std::vector<bool> orders =
      deterministic.empty() ? std::vector<bool>{base.deterministic} : parseOnOff(deterministic, "--deterministic");
  const std::vector<bool> measured = parseOnOff(loads, "--loads");
  const std::vector<std::pair<int, bool>> bodies = bodyRows(bodiesText, dynamic);
  const std::vector<std::size_t> counts = block ? parseSizes(sizes) : std::vector<std::size_t>{0};
  std::printf("fluid benchmark on %s: scene %s, steps %d..%d, medians per step\n", env.device.c_str(),
              scene.name.c_str(), w.first, w.last);
  Table table({"particles", "spacing",     "iters",        "determ.", "loads",      "bodies",        "dynamic",
               "cells",     "predict ms",  "count ms",     "scan ms", "reorder ms", "lambda ms",     "delta ms",
               "loads ms",  "velocity ms", "viscosity ms", "ms/step", "steps/s",    "bytes/particle"});
  Steps steps("bench fluid",
              int(counts.size() * iterationCounts.size() * orders.size() * measured.size() * bodies.size()));
  for (std::size_t n : counts)
    for (int k : iterationCounts)
      for (bool stable : orders)
        for (bool withLoads : measured)
          for (const auto& [bodyCount, bodiesMove] : bodies) {
            steps.begin((block ? "about " + std::to_string(n) + " particles" : scene.name) + ", " + std::to_string(k) +
                        " iterations, determ. " + (stable ? "on" : "off") + ", loads " + (withLoads ? "on" : "off") +
                        ", " + std::to_string(bodyCount) + (bodiesMove ? " dynamic" : " fixed") + " bodies");
            fluid::Params p = base;
            p.deterministic = stable;
            p.probes = loadProbes(base, withLoads);
            addFloatingBoxes(p, bodyCount, bodiesMove);
            if (block) {
              p.setSpacing(spacingFor(base, n));
              if (p.maxParticles > 0) p.maxParticles = std::max(p.maxParticles, int(n + n / 8));
            }
            p.iterations = k;
            fluid::Fluid model(env.shaders, p);
            const PassTimes t = timePasses(w.first, w.last - w.first, [&](gl::GpuProfiler& g) { model.stepOnce(&g); });
            const double perStep = t.frameMs();
            table.add({std::to_string(model.count()),
                       fixed(p.spacing(), 5),
                       std::to_string(k),
                       stable ? "on" : "off",
                       withLoads ? "on" : "off",
                       std::to_string(bodyCount),
                       bodiesMove ? "on" : "off",
                       std::to_string(model.cells()),
                       t.cell("fluid.predict", 4),
                       t.cell("fluid.count", 4),
                       t.cell("fluid.scan", 4),
                       t.cell("fluid.reorder", 4),
                       t.cell("fluid.lambda", 4),
                       t.cell("fluid.delta", 4),
                       t.cell("fluid.loads", 4),
                       t.cell("fluid.velocity", 4),
                       t.cell("fluid.viscosity", 4),
                       fixed(perStep, 4),
                       fixed(perStep > 0 ? 1000.0 / perStep : 0.0, 0),
                       std::to_string(model.bytesPerParticle())});
          }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addFluidBench(CLI::App& bench) {
  auto* sub =
      bench.add_subcommand("fluid", "fluid (PBF) step: ms per pass over a step window, steps/s, bytes per particle");
  struct Opts {
    std::string scene = "bench-fluid", sizes = "65536,1M", iterations = "4", deterministic, loads = "off", bodies = "0",
                dynamic = "on", window = "10:110";
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "scene (default bench-fluid)");
  sub->add_option("--n", o->sizes, "particle counts for block scenes, e.g. 65536,1M,4M");
  sub->add_option("--iterations", o->iterations, "solver iterations, one row each, e.g. 2,4,8");
  sub->add_option("--deterministic", o->deterministic,
                  "stable grid order (bit-identical runs) on or off, one row each, e.g. on,off");
  sub->add_option("--loads", o->loads,
                  "force probes on the floor and every obstacle off or on, one row each, e.g. off,on");
  sub->add_option("--bodies", o->bodies,
                  "dynamic boxes afloat at the water's surface, one row each, e.g. 0,10 (sim/water/bodies.h)");
  sub->add_option("--dynamic", o->dynamic, "those boxes dynamic or held still, one row each, e.g. on,off");
  sub->add_option("--steps", o->window, "timed step window FIRST:LAST");
  return {sub, [o](Env& env) {
            return run(env, o->scene, o->sizes, o->iterations, o->deterministic, o->loads, o->bodies, o->dynamic,
                       o->window);
          }};
}

}  // namespace tidepool::bench
