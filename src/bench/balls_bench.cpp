// `tidepool bench balls <scene> --n 65536,... --steps 10:310`: median GPU ms per step over a
// window of steps, split by pass, with steps per second and GPU bytes per ball. --n sets the
// ball count of lattice scenes (bench-lattice); other scenes run as they are. --reorder
// scatter,gather runs each size once per grid reorder mode (the scene's grid_reorder otherwise),
// --deterministic on,off once per grid order (stable: bit-identical runs; the scene's otherwise).
#include <cstdio>

#include "base/error.h"
#include "bench/bench.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"

namespace tidepool::bench {
namespace {

int run(Env& env, const std::string& sceneName, const std::string& sizes, const std::string& window,
        const std::string& reorder, const std::string& deterministic) {
  const Scene scene = loadScene(resolveScenePath(sceneName));
  const balls::Params base = ballsParams(scene);
  const StepWindow w = parseStepWindow(window);
  const bool lattice = base.fill == balls::Fill::Lattice;
  const std::vector<grid::ReorderMode> modes =
      reorder.empty() ? std::vector<grid::ReorderMode>{base.gridReorder} : parseReorderModes(reorder);
  const std::vector<bool> orders =
      deterministic.empty() ? std::vector<bool>{base.deterministic} : parseOnOff(deterministic, "--deterministic");
  std::printf("balls benchmark on %s: scene %s, steps %d..%d, medians per step\n", env.device.c_str(),
              scene.name.c_str(), w.first, w.last);
  Table table({"balls", "r", "cells", "reorder", "determ.", "count ms", "scan ms", "reorder ms", "drift ms",
               "collide ms", "obstacles ms", "ms/step", "steps/s", "bytes/ball"});
  std::vector<std::size_t> counts = lattice ? parseSizes(sizes) : std::vector<std::size_t>{0};
  for (std::size_t n : counts)
    for (grid::ReorderMode mode : modes)
      for (bool stable : orders) {
        balls::Params p = base;
        p.deterministic = stable;
        if (lattice) p.latticeCount = int(n);
        p.gridReorder = mode;
        balls::Balls model(env.shaders, p);
        const PassTimes t = timePasses(w.first, w.last - w.first, [&](gl::GpuProfiler& p) { model.stepOnce(&p); });
        const double perStep = t.frameMs();
        table.add({std::to_string(model.count()), fixed(model.radius(), 5), std::to_string(model.cells()),
                   grid::kReorderModeNames[std::size_t(mode)], stable ? "on" : "off", fixed(t.median("balls.count"), 4),
                   fixed(t.median("balls.scan"), 4), fixed(t.median("balls.reorder"), 4),
                   fixed(t.median("balls.drift"), 4), fixed(t.median("balls.collide"), 4),
                   fixed(t.median("balls.obstacles"), 4), fixed(perStep, 4),
                   fixed(perStep > 0 ? 1000.0 / perStep : 0.0, 0), std::to_string(model.bytesPerBall())});
      }
  return finish(env, table, "; its per-pass timer queries read 0");
}

}  // namespace

Benchmark addBallsBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("balls", "balls step: ms per pass over a step window, steps/s, bytes per ball");
  struct Opts {
    std::string scene = "bench-lattice", sizes = "65536,1M,4M,16M", window = "10:310", reorder, deterministic;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "scene (default bench-lattice)");
  sub->add_option("--n", o->sizes, "ball counts for lattice scenes, e.g. 65536,1M,16M");
  sub->add_option("--steps", o->window, "timed step window FIRST:LAST");
  sub->add_option("--reorder", o->reorder,
                  "grid reorder modes, one row each, e.g. scatter,gather (default: the scene's grid_reorder)");
  sub->add_option("--deterministic", o->deterministic,
                  "stable grid order (bit-identical runs) on or off, one row each, e.g. on,off");
  return {sub, [o](Env& env) { return run(env, o->scene, o->sizes, o->window, o->reorder, o->deterministic); }};
}

}  // namespace tidepool::bench
