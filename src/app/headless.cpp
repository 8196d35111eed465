#include "app/headless.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/fit_gpu.h"
#include "app/frame_writer.h"
#include "app/probe_log.h"
#include "base/log.h"
#include "base/progress.h"
#include "io/checkpoint_path.h"
#include "io/echo.h"
#include "io/video.h"
#include "render/particle_exporter.h"
#include "scene/checkpoint.h"
#include "scene/scene.h"

namespace tidepool {

namespace {

// --fit-gpu: the job with particles.resolution measured for its budget, in a context of its own.
RenderJob fitted(const RenderJob& job) {
  if (!job.fitBudgetMs) return job;
  const std::filesystem::path file = resolveScenePath(job.scene);
  const Scene scene = loadScene(file, job.paramOverrides);
  FitOptions options;
  options.budgetMs = *job.fitBudgetMs;
  options.width = job.width.value_or(scene.clip.width);
  options.height = job.height.value_or(scene.clip.height);
  RenderJob out = job;
  auto context = gl::createHeadlessContext({job.backend, job.debugGl});
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  out.paramOverrides = fitOverrides(file, job.paramOverrides, shaders, options);
  return out;
}

}  // namespace

std::string runText(const std::string& name, const StageIndicators& shown, int frames, int width, int height) {
  std::string text = name + ": ";
  if (shown.particles > 0) text += groupedCount(shown.particles) + (shown.countsCells ? " cells, " : " particles, ");
  return text + std::to_string(frames) + (frames == 1 ? " frame" : " frames") + " at " + std::to_string(width) + "x" +
         std::to_string(height);
}

int renderHeadless(const RenderJob& request) {
  const RenderJob job = fitted(request);
  const Scene scene = loadScene(resolveScenePath(job.scene), job.paramOverrides);
  const int frames = job.frames.value_or(scene.clip.frames);
  const int width = job.width.value_or(scene.clip.width);
  const int height = job.height.value_or(scene.clip.height);
  if (frames <= 0) throw Error("--frames must be at least 1");
  if (job.outDir.empty() && job.video.empty()) throw Error("nothing to write: give --out DIR and/or --video FILE");
  if (job.exportFormat && job.outDir.empty())
    throw Error("--export needs --out DIR, the folder for the exported frames");
  if (job.exportFormat && job.exportEvery < 1)
    throw Error("--every " + std::to_string(job.exportEvery) + " must be at least 1 (export every K-th frame)");
  const bool pngFrames = !job.outDir.empty() && !job.noFrames;

  std::unique_ptr<io::VideoWriter> video;
  if (!job.video.empty()) video = std::make_unique<io::VideoWriter>(job.video, width, height, scene.clip.fps);
  if (!job.outDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(job.outDir, ec);
    if (ec) throw Error("cannot create output folder '" + io::shownPath(job.outDir) + "': " + ec.message());
  }

  auto context = gl::createHeadlessContext({job.backend, job.debugGl});
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  auto stage = createStage(scene, shaders);
  // Frame numbers: a fresh run's frame i shows the state after i steps (frame 0 the initial
  // state); a resumed run goes on after the checkpoint's frame, each of its frames a step on, so
  // that its frames join the first run's as one clip, without the checkpoint's frame twice.
  const bool resumed = !job.resume.empty();
  std::uint64_t first = 0;
  if (resumed) {
    first = loadCheckpoint(*stage, scene, job.resume, job.paramOverrides) + 1;  // live --set keys on top
    log::info("resumed from " + job.resume.string() + " at t = " + std::to_string(stage->simTime()) +
              " s: frames from " + std::to_string(first));
  }
  const bool checkpoints = job.saveLast || !job.checkpoint.empty() || job.checkpointEvery > 0;
  const std::filesystem::path checkpoint =
      job.checkpoint.empty() ? defaultCheckpointPath(job.outDir, job.video, scene.file) : job.checkpoint;
  if (checkpoints) io::checkpointTarget(checkpoint);  // refuses a folder, pipe or device before the first frame
  CheckpointSchedule schedule(job.checkpointEvery, stage->simTime());
  int saved = 0;
  std::unique_ptr<ParticleExporter> exporter;
  std::unique_ptr<SurfaceMesher> mesher;  // --export surface
  if (job.surface) {
    const std::optional<SurfaceInput> water = stage->surfaceInput();
    if (!water) throw Error(scene.model + " has no water: --export surface needs a balls or fluid scene");
    mesher = std::make_unique<SurfaceMesher>(shaders);
    mesher->plan(*water, *job.surface);  // a grid that does not fit is refused before the run
  } else if (job.exportFormat) {
    checkExportable(scene.model, stage->exportSource(), *job.exportFormat);
  }
  if (job.exportFormat) exporter = std::make_unique<ParticleExporter>(job.outDir, *job.exportFormat, job.exportEvery);
  std::unique_ptr<ProbeLog> probeLog;      // the scene's probes beside the exported frames
  std::optional<ProbeReadings> unstepped;  // a fresh run's frame 0 (it only renders): read once
  if (exporter) {
    if (ProbeReadings r = stage->probes(); !r.columns.empty()) {
      if (!r.error.empty()) throw Error(r.error);  // a probe the model cannot measure: before any frame
      probeLog = std::make_unique<ProbeLog>(job.outDir / "probes.csv");
      if (!resumed) unstepped = std::move(r);
    }
  }
  double surfaceMs = 0;  // building the meshes (GPU work and the wait for their sizes)
  RenderTarget target(width, height);
  gl::GpuProfiler profiler;
  FrameWriter writer;
  Progress progress("rendering " + scene.name, frames, job.progress);
  progress.note(runText(scene.name, stage->indicators(), frames, width, height));
  const int measured = resumed ? 0 : 1;  // the first frame that steps (a fresh run's frame 0 only renders)

  for (int i = 0; i < frames; ++i) {
    const std::uint64_t frame = first + std::uint64_t(i);
    const double frameStart = progress.seconds();
    profiler.beginFrame();
    if (resumed || i > 0) stage->step(profiler);
    if (const auto d = stage->divergence()) throw Error(d->message);
    if (checkpoints && i + 1 < frames && schedule.due(stage->simTime())) {
      saveCheckpoint(*stage, scene, checkpoint, frame);
      ++saved;
    }
    stage->render(target, profiler);
    profiler.endFrame();
    if (exporter) {
      // After render(): a view may set what the state means (the swarm's aspect, its image colours).
      if (exporter->due(int(frame)) && mesher) {
        const auto start = std::chrono::steady_clock::now();
        mesher->build(*stage->surfaceInput(), *job.surface);
        surfaceMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        exporter->capture(int(frame), stage->simTime(), mesher->exportSource());  // back a frame or two later
      } else if (exporter->due(int(frame))) {
        exporter->capture(int(frame), stage->simTime(), *stage->exportSource());
      }
      if (i == 0) exporter->writeObstacles(stage->exportObstacles());
      if (probeLog && exporter->due(int(frame)))
        probeLog->write(frame, stage->simTime(), i == 0 && unstepped ? *unstepped : stage->probes());
      exporter->poll();
    }
    std::vector<std::uint8_t> pixels = video || pngFrames ? target.readRgba8() : std::vector<std::uint8_t>();
    if (video) video->write(pixels);
    if (pngFrames) {
      writer.write(job.outDir / frameFileName(frame), io::Image{width, height, std::move(pixels)});
    }
    if (i == measured) {
      const double now = progress.seconds();
      progress.note(scene.name + ": " + estimateText(now - frameStart, now, i + 1, frames, "frames"));
    }
    progress.update(i + 1);
  }
  writer.finish();
  if (exporter) exporter->finish();
  stage->flushChecks();
  if (const auto d = stage->divergence()) throw Error(d->message);
  if (checkpoints) {
    saveCheckpoint(*stage, scene, checkpoint, first + std::uint64_t(frames - 1));
    log::info("wrote checkpoint " + checkpoint.string() + " at t = " + std::to_string(stage->simTime()) + " s (" +
              std::to_string(saved + 1) + " saved)");
  }
  if (video) video->close();
  progress.finish();
  if (mesher) {
    char line[160];
    std::snprintf(line, sizeof line, "water surface: %.2f ms per exported frame to build the mesh (%zu triangles last)",
                  surfaceMs / std::max(1, exporter->written()), mesher->counts().triangles);
    log::info(line);
  }
  if (exporter) log::info(exporter->summary());
  if (pngFrames)
    log::info("wrote " + std::to_string(frames) + " frames (" + std::to_string(width) + "x" + std::to_string(height) +
              ") to " + std::filesystem::absolute(job.outDir).string() + "/frame_*.png" +
              (resumed ? " (frames " + std::to_string(first) + " to " + std::to_string(first + frames - 1) + ")" : ""));
  if (video) log::info("wrote video " + std::filesystem::absolute(job.video).string());
  if (pngFrames)
    if (const std::string stale = staleFramesWarning(job.outDir, first + std::uint64_t(frames - 1)); !stale.empty())
      log::warn(stale);
  return frames;
}

}  // namespace tidepool
