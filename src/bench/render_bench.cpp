// `tidepool bench render [scene] --n 1M --size 1920x1080 [--raster compute|fragment|both]
// [--look seed,clear,ocean]`: median GPU ms per pass of the balls renderer in both modes (and each
// look asked for, else the scene's), simulation excluded: scene (the raster
// pass drawing the obstacles; `-` when the scene has none, as the lattice), the sphere impostors
// (fragment raster: gbuffer, thickness; compute raster: depth splat with the thickness, id,
// resolve), blur, compose (a compute pass, with the box). The balls are the scene's (--n sets the
// count of lattice scenes), settled for a few steps first so they are not a perfect lattice, and
// seen from the scene's camera.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <regex>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "io/echo.h"
#include "render/balls_view.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"

namespace tidepool::bench {
namespace {

struct Options {
  std::string scene = "bench-lattice", sizes = "1M", image = "1920x1080", raster = "both", looks;
  int settle = 20;  // simulation steps before timing
};

glm::ivec2 parseImage(const std::string& text) {
  static const std::regex form(R"((\d+)x(\d+))");
  std::smatch m;
  if (!std::regex_match(text, m, form) || std::stoi(m[1]) <= 0 || std::stoi(m[2]) <= 0)
    throw Error("--size '" + io::printable(text) + "' is not WIDTHxHEIGHT (e.g. 1920x1080)");
  return {std::stoi(m[1]), std::stoi(m[2])};
}

constexpr const char* kPasses[] = {"balls.scene",       "balls.gbuffer",  "balls.thickness",
                                   "balls.splat.depth", "balls.splat.id", "balls.splat.resolve",
                                   "balls.blur",        "balls.caustics", "balls.compose"};

std::vector<BallsRaster> parseRaster(const std::string& text) {
  if (text == "both") return {BallsRaster::Compute, BallsRaster::Fragment};
  for (std::size_t i = 0; i < kBallsRasterNames.size(); ++i)
    if (text == kBallsRasterNames[i]) return {BallsRaster(i)};
  throw Error("--raster '" + text + "' is not compute, fragment or both");
}

// The looks of --look, one row each; none: the scene's own (nullopt).
std::vector<std::optional<WaterLook>> parseLooks(const std::string& text) {
  if (text.empty()) return {std::nullopt};
  std::vector<std::optional<WaterLook>> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto* it = std::find(kWaterLookNames.begin(), kWaterLookNames.end(), name);
    if (it == kWaterLookNames.end())
      throw Error("--look '" + io::printable(name) + "' is not one of: seed, clear, ocean");
    out.push_back(WaterLook(it - kWaterLookNames.begin()));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

int run(Env& env, const Options& o) {
  const Scene scene = loadScene(resolveScenePath(o.scene));
  const BallsSceneParams& params = ballsScene(scene);
  const balls::Params& base = params.model;
  const glm::ivec2 image = parseImage(o.image);
  const std::vector<BallsRaster> rasters = parseRaster(o.raster);
  const std::vector<std::optional<WaterLook>> looks = parseLooks(o.looks);
  const bool lattice = base.fill == water::Fill::Lattice;
  std::printf("render benchmark on %s: scene %s, %dx%d, %d settling steps, medians of %d frames\n", env.device.c_str(),
              scene.name.c_str(), image.x, image.y, o.settle, env.common.repeats);
  Table table({"balls", "mode", "look", "raster", "scene ms", "gbuffer ms", "thickness ms", "splat ms", "id ms",
               "resolve ms", "blur ms", "caustics ms", "compose ms", "frame ms"});
  const std::vector<std::size_t> counts = lattice ? parseSizes(o.sizes) : std::vector<std::size_t>{0};
  Steps steps("bench render", int(counts.size() * looks.size() * rasters.size() * 2));
  for (std::size_t n : counts) {
    balls::Params p = base;
    if (lattice) p.latticeCount = int(n);
    balls::Balls model(env.shaders, p);
    for (int i = 0; i < o.settle; ++i) model.stepOnce();
    RenderTarget target(image.x, image.y);
    BallsView view(env.shaders);
    view.camera().params() = params.view.camera;
    for (const std::optional<WaterLook>& look : looks)
      for (BallsRaster raster : rasters)
        for (BallsMode mode : {BallsMode::Balls, BallsMode::Water}) {
          view.params() = params.view.look;
          if (look) applyLook(view.params(), *look);
          view.params().raster = raster;
          view.params().mode = mode;
          const char* lookName = kWaterLookNames[int(view.params().look)];
          steps.begin(std::to_string(model.count()) + " balls, " + kBallsModeNames[int(mode)] + ", " + lookName + ", " +
                      kBallsRasterNames[int(raster)] + " raster");
          const PassTimes t = timePasses(env.common.warmup, env.common.repeats,
                                         [&](gl::GpuProfiler& p) { view.render(model, target, p); });
          std::vector<std::string> row = {std::to_string(model.count()), kBallsModeNames[int(mode)], lookName,
                                          kBallsRasterNames[int(raster)]};
          for (const char* pass : kPasses) row.push_back(t.cell(pass, 4));
          row.push_back(fixed(t.frameMs(), 4));
          table.add(row);
        }
  }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addRenderBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("render", "balls renderer: ms per pass in balls and water modes");
  auto o = std::make_shared<Options>();
  sub->add_option("scene", o->scene, "balls scene (default bench-lattice)");
  sub->add_option("--n", o->sizes, "ball counts for lattice scenes, e.g. 65536,1M");
  sub->add_option("--size", o->image, "image WIDTHxHEIGHT (default 1920x1080)");
  sub->add_option("--settle", o->settle, "simulation steps before timing (default 20)");
  sub->add_option("--raster", o->raster, "sphere impostors: compute, fragment or both (default both)");
  sub->add_option("--look", o->looks, "looks, one row each, e.g. seed,clear,ocean (default: the scene's)");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
