// `tidepool bench balls <scene> --n 65536,... --steps 10:310`: median GPU ms per step over a
// window of steps (GL_TIMESTAMP between steps, as CUDA events time the sample's; their mean and
// the wall clock of the window beside it), split by pass (GL_TIME_ELAPSED), with steps per second
// and GPU bytes per ball. --n sets the ball count of lattice scenes (bench-lattice) and of
// block-filled ones (the scene refined, sim/water/setup.h's refine, until its block holds about n
// balls); other scenes run as they are. --deterministic on,off runs each size once per grid order
// (stable: bit-identical runs; the scene's otherwise). --loads and --bodies add force probes and
// floating boxes as bench fluid does (bench/water_rows.h).
#include <cstdio>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "bench/water_rows.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"
#include "sim/water/water_init.h"

namespace tidepool::bench {
namespace {

struct Options {
  std::string scene = "bench-lattice", sizes = "65536,1M,4M,16M", window = "10:310", deterministic;
  std::string loads = "off", bodies = "0", dynamic = "on";
};

// A block-filled scene refined until its block holds about n balls.
balls::Params withBalls(const balls::Params& p, std::size_t n) {
  balls::Params q = p;
  balls::refine(q, std::cbrt(double(n) / water::estimatedWater(balls::resolved(p))));
  return q;
}

// The rows of the table: the scene's parameters once per size, grid order, loads and bodies.
struct Row {
  balls::Params params;
  bool loads = false;
  int bodies = 0;
  bool dynamic = false;
};
std::vector<Row> variants(const Options& o, const balls::Params& base) {
  const bool lattice = base.fill == water::Fill::Lattice, block = base.fill == water::Fill::Block;
  const std::vector<bool> orders =
      o.deterministic.empty() ? std::vector<bool>{base.deterministic} : parseOnOff(o.deterministic, "--deterministic");
  const std::vector<bool> measured = parseOnOff(o.loads, "--loads");
  const std::vector<std::pair<int, bool>> bodies = bodyRows(o.bodies, o.dynamic);
  std::vector<Row> out;
  for (std::size_t n : lattice || block ? parseSizes(o.sizes) : std::vector<std::size_t>{0})
    for (bool stable : orders)
      for (bool withLoads : measured)
        for (const auto& [bodyCount, bodiesMove] : bodies) {
          balls::Params p = block ? withBalls(base, n) : base;
          p.deterministic = stable;
          if (lattice) p.latticeCount = int(n);
          p.probes = loadProbes(base, withLoads);
          addFloatingBoxes(p, bodyCount, bodiesMove);
          out.push_back({p, withLoads, bodyCount, bodiesMove});
        }
  return out;
}

int run(Env& env, const Options& o) {
  const Scene scene = loadScene(resolveScenePath(o.scene));
  const balls::Params base = ballsParams(scene);
  const StepWindow w = parseStepWindow(o.window);
  const std::vector<Row> rows = variants(o, base);
  std::printf("balls benchmark on %s: scene %s, steps %d..%d, medians per step\n", env.device.c_str(),
              scene.name.c_str(), w.first, w.last);
  Table table({"balls",    "r",       "cells",      "determ.",  "loads",      "bodies",   "dynamic",
               "count ms", "scan ms", "reorder ms", "drift ms", "collide ms", "loads ms", "obstacles ms",
               "ms/step",  "steps/s", "bytes/ball", "windows",  "clock",      "mean ms",  "sustained ms"});
  Steps steps("bench balls", int(rows.size()));
  for (const Row& row : rows) {
    const balls::Params& p = row.params;
    steps.begin((p.fill == water::Fill::Lattice ? "about " + std::to_string(p.latticeCount) + " balls" : scene.name) +
                ", determ. " + (p.deterministic ? "on" : "off") + ", loads " + (row.loads ? "on" : "off") + ", " +
                std::to_string(row.bodies) + (row.dynamic ? " dynamic" : " fixed") + " bodies");
    balls::Balls model(env.shaders, p);
    // A windowed step reads its windows back part-way: its timer queries miss part of it, so it is
    // timed by the wall clock.
    const bool wall = gl::needsWindows(model.count(), sizeof(glm::vec4));
    const PassTimes t = timePasses(
        w.first, w.last - w.first, [&](gl::GpuProfiler& prof) { model.stepOnce(&prof); }, wall);
    const double perStep = t.frameMs();
    table.add({std::to_string(model.count()),
               fixed(model.radius(), 5),
               std::to_string(model.cells()),
               p.deterministic ? "on" : "off",
               row.loads ? "on" : "off",
               std::to_string(row.bodies),
               row.dynamic ? "on" : "off",
               t.cell("balls.count", 4),
               t.cell("balls.scan", 4),
               t.cell("balls.reorder", 4),
               t.cell("balls.drift", 4),
               t.cell("balls.collide", 4),
               t.cell("balls.loads", 4),
               t.cell("balls.obstacles", 4),
               fixed(perStep, 4),
               fixed(perStep > 0 ? 1000.0 / perStep : 0.0, 0),
               std::to_string(model.bytesPerBall()),
               std::to_string(model.collideWindows()),
               !t.wall.empty()    ? "wall"
               : t.stream.empty() ? "gpu"
                                  : "stream",
               t.stream.empty() ? kNotMeasured : fixed(t.streamMeanMs(), 4),
               fixed(t.sustainedMs, 4)});
  }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addBallsBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("balls", "balls step: ms per pass over a step window, steps/s, bytes per ball");
  auto o = std::make_shared<Options>();
  sub->add_option("scene", o->scene, "scene (default bench-lattice)");
  sub->add_option("--n", o->sizes, "ball counts for lattice and block-filled scenes, e.g. 65536,1M,16M");
  sub->add_option("--loads", o->loads,
                  "force probes on the floor and every obstacle off or on, one row each, e.g. off,on");
  sub->add_option("--bodies", o->bodies,
                  "dynamic boxes afloat at the water's surface, one row each, e.g. 0,10 (sim/water/bodies.h)");
  sub->add_option("--dynamic", o->dynamic, "those boxes dynamic or held still, one row each, e.g. on,off");
  sub->add_option("--steps", o->window, "timed step window FIRST:LAST");
  sub->add_option("--deterministic", o->deterministic,
                  "stable grid order (bit-identical runs) on or off, one row each, e.g. on,off");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
