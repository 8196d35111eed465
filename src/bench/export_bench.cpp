// `tidepool bench export [scene] [--format vtk,ply] [--out DIR]`: what exporting the particles (or
// the heightfield) of a frame costs the render loop, per format. The scene's stage steps a frame at
// a time and exports every frame (render/particle_exporter.h: start the GPU copy, write what came
// back). Each timed frame is clocked twice on the CPU wall clock, in the same frame: after its step
// (glFinish) and after its export (glFinish), so "frame ms" is the step alone and "frame+export ms"
// the whole frame, never below it. The exporter's own means per exported frame follow: starting
// the copy (what the GPU queue sees at the frame), reading it back, converting to points, writing
// the file; MB copied and MB on disk per frame.
#include <unistd.h>
#include <chrono>
#include <cstdio>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "render/particle_exporter.h"
#include "scene/scene.h"

namespace tidepool::bench {
namespace {

// The particles' formats: the first two of io::ExportFormat (OBJ is for surfaces: bench surface).
constexpr std::array<const char*, 2> kParticleFormats = {io::kExportFormatNames[0], io::kExportFormatNames[1]};

struct Options {
  std::string scene = "dam-break", formats = "vtk,ply", out;
  int frames = 0;  // 0: common.repeats
};

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int run(Env& env, const Options& o) {
  const Scene scene = loadScene(resolveScenePath(o.scene));
  const std::vector<io::ExportFormat> formats = parseChoices<io::ExportFormat>(o.formats, kParticleFormats, "--format");
  auto stage = createStage(scene, env.shaders);
  for (io::ExportFormat format : formats) checkExportable(scene.model, stage->exportSource(), format);
  const int frames = o.frames > 0 ? o.frames : env.common.repeats;
  const std::filesystem::path root =
      o.out.empty() ? std::filesystem::temp_directory_path() / ("tidepool-bench-export-" + std::to_string(getpid()))
                    : std::filesystem::path(o.out);
  gl::GpuProfiler profiler;
  RenderTarget target(scene.clip.width, scene.clip.height);
  stage->render(target, profiler);  // a view may set what the state means (the swarm's aspect)
  for (int i = 0; i < env.common.warmup; ++i) stage->step(profiler);
  std::printf(
      "export benchmark on %s: scene %s, %zu points (particles or cells), %d frames each, every frame exported\n",
      env.device.c_str(), scene.name.c_str(), stage->model() ? stage->model()->count() : 0, frames);
  Table table({"points", "format", "frame ms", "frame+export ms", "copy ms", "read back ms", "convert ms", "write ms",
               "MB copied", "MB file"});
  Steps steps("bench export", int(formats.size()));
  for (io::ExportFormat format : formats) {
    steps.begin(std::string(io::kExportFormatNames[std::size_t(format)]) + ", " + std::to_string(frames) + " frames");
    const std::filesystem::path folder = root / io::exportExtension(format);
    std::vector<double> plain, exported;  // per frame, the same frames: the step, the step and its export
    double fileBytes = 0;
    {
      ParticleExporter exporter(folder, format, 1);
      for (int i = 0; i < frames; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        stage->step(profiler);
        glFinish();
        plain.push_back(msSince(start));
        exporter.capture(i, stage->simTime(), *stage->exportSource());
        exporter.poll();
        glFinish();
        exported.push_back(msSince(start));
        Steps::tick(i + 1, frames, "frames");
      }
      exporter.finish();
      const ParticleExporter::Cost& c = exporter.cost();
      const double n = std::max(1, exporter.written());
      fileBytes =
          double(std::filesystem::file_size(exporter.series().framePath(0, stage->exportSource()->heightField)));
      table.add({std::to_string(stage->model() ? stage->model()->count() : 0),
                 io::kExportFormatNames[std::size_t(format)], fixed(median(plain), 3), fixed(median(exported), 3),
                 fixed(c.captureMs / n, 3), fixed((c.readMs + c.waitMs) / n, 3), fixed(c.convertMs / n, 3),
                 fixed(c.writeMs / n, 3), fixed(double(c.bytes) / n / 1e6, 3), fixed(fileBytes / 1e6, 3)});
    }
    if (o.out.empty()) std::filesystem::remove_all(folder);
  }
  steps.finish();
  if (o.out.empty()) std::filesystem::remove_all(root);
  return finish(env, table, "; every column is CPU wall clock");
}

}  // namespace

Benchmark addExportBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("export", "particle export: ms per exported frame, per format");
  auto o = std::make_shared<Options>();
  sub->add_option("scene", o->scene, "balls, fluid, life or swarm scene (default dam-break)");
  sub->add_option("--format", o->formats, "vtk, ply or vtk,ply (default both)");
  sub->add_option("--frames", o->frames, "timed frames per format (default: --repeats)")->check(CLI::Range(1, 100000));
  sub->add_option("--out", o->out, "keep the files in this folder (default: a temporary folder, removed)");
  return {sub, [o](Env& env) { return run(env, *o); }};
}

}  // namespace tidepool::bench
