// `tidepool bench balls <scene> --n 65536,... --steps 10:310`: median GPU ms per step over a
// window of steps (GL_TIMESTAMP between steps, as CUDA events time the sample's; their mean and
// the wall clock of the window beside it), split by pass (GL_TIME_ELAPSED), with steps per second
// and GPU bytes per ball. --n sets the ball count of lattice scenes (bench-lattice); other scenes
// run as they are. --reorder scatter,gather runs each size once per grid reorder mode (the
// scene's grid_reorder otherwise),
// --deterministic on,off once per grid order (stable: bit-identical runs; the scene's otherwise),
// --neighbours grid,lists once per neighbour search, --skin 0.2,0.4 once per list skin (lists),
// --count pass,collide once per place of the grid's count (its own pass, or in the collide);
// --timers queued,isolated,off once per way of clocking the passes (bench.h, Timers).
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>

#include "base/error.h"
#include "bench/bench.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"

namespace tidepool::bench {
namespace {

std::vector<float> parseSkins(const std::string& text) {
  auto one = [](const std::string& token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (token.empty() || *end != '\0' || !(v >= 0.01 && v <= 4.0))
      throw Error("--skin '" + token + "' is not a fraction of r in [0.01, 4]");
    return float(v);
  };
  return parseList(text, one, "--skin: nothing given (e.g. 0.2,0.4)");
}

struct Options {
  std::string scene = "bench-lattice", sizes = "65536,1M,4M,16M", window = "10:310", reorder, deterministic, neighbours,
              skin, count, timers;
  bool wall = false;  // every row timed by the wall clock around glFinish
};

// One row of the table: the scene's parameters with the bench's choices applied.
struct Variant {
  balls::Params params;
  bool countInCollide = true;
  Timers timers = Timers::Queued;
};

std::vector<Variant> variants(const Options& o, const balls::Params& base) {
  const bool lattice = base.fill == balls::Fill::Lattice;
  const std::vector<grid::ReorderMode> modes =
      o.reorder.empty() ? std::vector<grid::ReorderMode>{base.gridReorder} : parseReorderModes(o.reorder);
  const std::vector<bool> orders =
      o.deterministic.empty() ? std::vector<bool>{base.deterministic} : parseOnOff(o.deterministic, "--deterministic");
  const std::vector<balls::Neighbours> searches =
      o.neighbours.empty() ? std::vector<balls::Neighbours>{base.neighbours}
                           : parseChoices<balls::Neighbours>(o.neighbours, balls::kNeighboursNames, "--neighbours");
  const std::vector<float> skins = o.skin.empty() ? std::vector<float>{base.skin} : parseSkins(o.skin);
  static constexpr std::array<const char*, 2> kCountNames = {"pass", "collide"};
  const std::vector<int> countIn =
      o.count.empty() ? std::vector<int>{1} : parseChoices<int>(o.count, kCountNames, "--count");
  const std::vector<Timers> clocks =
      o.timers.empty() ? std::vector<Timers>{Timers::Queued} : parseChoices<Timers>(o.timers, kTimersNames, "--timers");
  std::vector<Variant> out;
  for (std::size_t n : lattice ? parseSizes(o.sizes) : std::vector<std::size_t>{0})
    for (grid::ReorderMode mode : modes)
      for (bool stable : orders)
        for (balls::Neighbours search : searches)
          for (float skin : search == balls::Neighbours::Lists ? skins : std::vector<float>{base.skin})
            for (int fused : countIn)
              for (Timers clock : clocks) {
                Variant v{base, fused == 1, clock};
                v.params.deterministic = stable;
                if (lattice) v.params.latticeCount = int(n);
                v.params.gridReorder = mode;
                v.params.neighbours = search;
                v.params.skin = skin;
                out.push_back(v);
              }
  return out;
}

int run(Env& env, const Options& o) {
  const Scene scene = loadScene(resolveScenePath(o.scene));
  const balls::Params base = ballsParams(scene);
  const StepWindow w = parseStepWindow(o.window);
  const std::vector<Variant> rows = variants(o, base);
  std::printf("balls benchmark on %s: scene %s, steps %d..%d, medians per step\n", env.device.c_str(),
              scene.name.c_str(), w.first, w.last);
  Table table({"balls",    "r",           "cells",       "reorder",    "determ.",  "search",     "count in",
               "count ms", "scan ms",     "reorder ms",  "lists ms",   "drift ms", "collide ms", "obstacles ms",
               "ms/step",  "steps/s",     "steps/build", "bytes/ball", "windows",  "clock",      "timers",
               "mean ms",  "sustained ms"});
  for (const Variant& v : rows) {
    const balls::Params& p = v.params;
    balls::Balls model(env.shaders, p);
    model.countInCollide(v.countInCollide);
    // A windowed step reads its windows back part-way: its timer queries miss part of it, so it is
    // timed by the wall clock (as --wall times every row).
    const bool wall = o.wall || gl::needsWindows(model.count(), sizeof(glm::vec4));
    const PassTimes t = timePasses(
        w.first, w.last - w.first, [&](gl::GpuProfiler& prof) { model.stepOnce(&prof); }, wall, v.timers);
    const double perStep = t.frameMs();
    // Lists: the gate's section (count, scan, permutation, build) is timed as "balls.lists";
    // steps per build over the whole run.
    std::string searchName = balls::kNeighboursNames[std::size_t(p.neighbours)], perBuild = "";
    if (model.listsActive()) {
      const balls::Balls::ListCounts c = model.listCounts();
      searchName += " " + fixed(p.skin, 2);
      perBuild = fixed(c.rebuilds > 0 ? double(c.steps) / c.rebuilds : 0.0, 1);
    }
    table.add({std::to_string(model.count()),
               fixed(model.radius(), 5),
               std::to_string(model.cells()),
               grid::kReorderModeNames[std::size_t(p.gridReorder)],
               p.deterministic ? "on" : "off",
               searchName,
               v.countInCollide ? "collide" : "pass",
               fixed(t.median("balls.count"), 4),
               fixed(t.median("balls.scan"), 4),
               fixed(t.median("balls.reorder"), 4),
               fixed(t.median("balls.lists"), 4),
               fixed(t.median("balls.drift"), 4),
               fixed(t.median("balls.collide"), 4),
               fixed(t.median("balls.obstacles"), 4),
               fixed(perStep, 4),
               fixed(perStep > 0 ? 1000.0 / perStep : 0.0, 0),
               perBuild,
               std::to_string(model.bytesPerBall()),
               std::to_string(model.collideWindows()),
               !t.wall.empty()    ? "wall"
               : t.stream.empty() ? "gpu"
                                  : "stream",
               kTimersNames[std::size_t(v.timers)],
               fixed(t.streamMeanMs(), 4),
               fixed(t.sustainedMs, 4)});
  }
  return finish(env, table, "; its per-pass timer queries read 0");
}

}  // namespace

Benchmark addBallsBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("balls", "balls step: ms per pass over a step window, steps/s, bytes per ball");
  auto o = std::make_shared<Options>();
  sub->add_option("scene", o->scene, "scene (default bench-lattice)");
  sub->add_option("--n", o->sizes, "ball counts for lattice scenes, e.g. 65536,1M,16M");
  sub->add_option("--steps", o->window, "timed step window FIRST:LAST");
  sub->add_option("--reorder", o->reorder,
                  "grid reorder modes, one row each, e.g. scatter,gather (default: the scene's grid_reorder)");
  sub->add_option("--deterministic", o->deterministic,
                  "stable grid order (bit-identical runs) on or off, one row each, e.g. on,off");
  sub->add_option("--neighbours", o->neighbours, "neighbour searches, one row each: grid, lists or grid,lists");
  sub->add_option("--skin", o->skin, "list skins (fraction of r), one row each with lists, e.g. 0.2,0.4");
  sub->add_flag("--wall", o->wall,
                "time every row by the wall clock around glFinish (windowed rows always are: their steps read back)");
  sub->add_option("--count", o->count,
                  "where the grid counts the balls, one row each: collide (in the collide's write, the default "
                  "without obstacles and lists) or pass (a count pass), e.g. pass,collide");
  sub->add_option("--timers", o->timers,
                  "how the passes are clocked, one row each: queued (timer queries, steps back to back), isolated "
                  "(a glFinish before each pass: its own time) or off (no per-pass queries; ms/step is still timed)");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
