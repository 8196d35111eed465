// `tidepool bench surface [scene] --particles N --resolution R[,R...] [--steps S] [--format ply]`:
// what building the water surface (render/surface_mesher.h) costs per exported frame. --particles
// sets the count of a block-filled fluid or balls scene (default bench-fluid) by choosing the
// spacing that fills its block with about N particles; the scene then runs S frames (default 15,
// the dam starts to break) and its surface is built --repeats times at each resolution. Columns:
// the mesh's size, GPU ms per pass and their sum "GPU ms" (timer queries; '-' on a software
// renderer, whose timers read 0), "build ms": the CPU wall clock of the same builds from the call
// to the finished mesh (the passes, the wait for the mesh's size, then glFinish), so never below
// GPU ms; then the export's means per frame: reading the mesh back, converting it, writing the file.
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "render/particle_exporter.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"

namespace tidepool::bench {
namespace {

struct Options {
  std::string scene = "bench-fluid", resolutions = "128", format = "ply", out;
  std::size_t particles = 0;  // 0: the scene's own
  int steps = 15;             // frames run before measuring
  float smoothing = SurfaceParams{}.smoothing, iso = SurfaceParams{}.iso;
};

// Overrides of a block-filled scene's params for about n particles (spacing for the fluid's
// cubic lattice, radius for the balls' hexagonal packing: √2 per (2r)³).
io::Json particleOverrides(const Scene& scene, std::size_t n) {
  const water::Setup w = scene.model == "fluid"   ? water::Setup(fluidScene(scene).model)
                         : scene.model == "balls" ? water::Setup(ballsParams(scene))
                                                  : throw Error("--particles needs a balls or fluid scene");
  if (w.fill != water::Fill::Block) throw Error("--particles needs a block-filled scene (e.g. bench-fluid)");
  const glm::vec3 extent = glm::max(glm::min(w.fillMax, w.domainMax) - glm::max(w.fillMin, w.domainMin), 0.0f);
  const double volume = double(extent.x) * extent.y * extent.z;
  if (scene.model == "fluid") return {{"particles", {{"spacing", std::cbrt(volume / double(n))}}}};
  return {{"particles", {{"radius", 0.5 * std::cbrt(std::sqrt(2.0) * volume / double(n))}}}};
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int run(Env& env, const Options& o) {
  const std::filesystem::path file = resolveScenePath(o.scene);
  Scene scene = loadScene(file);
  if (o.particles > 0) scene = loadScene(file, particleOverrides(scene, o.particles));
  const io::ExportFormat format = io::parseSurfaceFormat(o.format);
  std::vector<int> resolutions;
  for (std::size_t r : parseSizes(o.resolutions)) resolutions.push_back(int(r));
  auto stage = createStage(scene, env.shaders);
  if (!stage->surfaceInput()) throw Error(scene.model + " has no water: bench surface needs a balls or fluid scene");
  gl::GpuProfiler stepProfiler;
  for (int i = 0; i < o.steps; ++i) stage->step(stepProfiler);
  glFinish();
  const SurfaceInput input = *stage->surfaceInput();
  SurfaceMesher mesher(env.shaders);
  for (int r : resolutions) mesher.plan(input, {r, o.smoothing, o.iso});  // refuse before measuring
  std::printf(
      "surface benchmark on %s: scene %s, %zu particles after %d frames, smoothing %.2g r, iso %.2g, %d "
      "builds each\n",
      env.device.c_str(), scene.name.c_str(), input.count, o.steps, double(o.smoothing), double(o.iso),
      env.common.repeats);
  const std::filesystem::path root =
      o.out.empty() ? std::filesystem::temp_directory_path() / ("tidepool-bench-surface-" + std::to_string(getpid()))
                    : std::filesystem::path(o.out);
  Table table({"particles", "resolution", "corners", "triangles", "splat ms", "classify ms", "scan ms", "emit ms",
               "GPU ms", "build ms", "read back ms", "convert ms", "write ms", "MB file"});
  Steps steps("bench surface", int(resolutions.size()));
  for (int r : resolutions) {
    steps.begin("resolution " + std::to_string(r));
    const SurfaceParams params{r, o.smoothing, o.iso};
    std::vector<double> buildWall;
    wakeGpu(env.shaders);
    // Each build waits for its last pass (glFinish) so that the wall clock covers the GPU work it
    // times; the timed frames are the warm-up's followers, in order: buildWall keeps the last ones.
    const PassTimes t = timePasses(env.common.warmup, env.common.repeats, [&](gl::GpuProfiler& profiler) {
      glFinish();
      const auto start = std::chrono::steady_clock::now();
      mesher.build(input, params, &profiler);
      glFinish();
      buildWall.push_back(msSince(start));
    });
    buildWall.erase(buildWall.begin(),
                    buildWall.end() - std::min<std::ptrdiff_t>(buildWall.size(), env.common.repeats));
    const std::filesystem::path folder = root / std::to_string(r);
    ParticleExporter exporter(folder, format, 1);
    for (int i = 0; i < env.common.repeats; ++i) {
      mesher.build(input, params);
      exporter.capture(i, stage->simTime(), mesher.exportSource());
      exporter.poll();
    }
    exporter.finish();
    const ParticleExporter::Cost& c = exporter.cost();
    const double n = std::max(1, exporter.written());
    const double fileBytes = double(std::filesystem::file_size(exporter.series().surfacePath(0)));
    const SurfaceGrid& g = mesher.grid();
    table.add({std::to_string(input.count), std::to_string(r),
               std::to_string(g.corners.x) + "x" + std::to_string(g.corners.y) + "x" + std::to_string(g.corners.z),
               std::to_string(mesher.counts().triangles), t.cell("surface.splat", 3), t.cell("surface.classify", 3),
               t.cell("surface.scan", 3), t.cell("surface.emit", 3),
               t.timersRead() ? fixed(median(t.totals), 3) : kNotMeasured, fixed(median(buildWall), 3),
               fixed((c.readMs + c.waitMs) / n, 3), fixed(c.convertMs / n, 3), fixed(c.writeMs / n, 3),
               fixed(fileBytes / 1e6, 3)});
    if (o.out.empty()) std::filesystem::remove_all(folder);
  }
  steps.finish();
  if (o.out.empty()) std::filesystem::remove_all(root);
  return finish(env, table, "; build ms and the export's columns are CPU wall clock");
}

}  // namespace

Benchmark addSurfaceBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("surface", "water surface mesh: ms per frame for splat, marching cubes, export");
  auto o = std::make_shared<Options>();
  sub->add_option("scene", o->scene, "balls or fluid scene (default bench-fluid)");
  sub->add_option("--particles", o->particles, "about this many particles (block-filled scenes; default: the scene's)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 28));
  sub->add_option("--resolution", o->resolutions, "grid cells along the longest axis, e.g. 128,256 (default 128)");
  sub->add_option("--steps", o->steps, "frames the scene runs before measuring (default 15)")
      ->check(CLI::Range(0, 100000));
  sub->add_option("--smoothing", o->smoothing, "kernel reach in particle radii (default 4)");
  sub->add_option("--iso", o->iso, "density level of the surface (default 0.5)");
  sub->add_option("--format", o->format, "ply, obj or vtk (default ply)");
  sub->add_option("--out", o->out, "keep the files in this folder (default: a temporary folder, removed)");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
