// Headless rendering of a scene: a clip of PNG frames and/or a video, with a progress bar.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "gl/context.h"
#include "io/export_series.h"
#include "io/json.h"
#include "render/surface_mesher.h"
#include "scene/stage.h"

namespace tidepool {

struct RenderJob {
  std::string scene;                             // path or bare name (assets/scenes/<name>.json)
  io::Json paramOverrides;                       // scene params from --set, --rules (resumed: live keys only)
  std::optional<int> frames;                     // default: the scene's clip.frames
  std::optional<int> width, height;              // default: the scene's clip size
  std::filesystem::path outDir;                  // PNG frames (frame_00000.png ...); empty: none
  std::filesystem::path video;                   // .mp4 through ffmpeg; empty: none
  std::optional<io::ExportFormat> exportFormat;  // particles to outDir every exportEvery frames (frame 0 too)
  int exportEvery = 1;
  std::optional<SurfaceParams> surface;  // with exportFormat (ply, obj, vtk): the water surface, not the particles
  bool noFrames = false;                 // no PNG frames in outDir (with an export)
  std::filesystem::path resume;          // a checkpoint to start from (scene/checkpoint.h); empty: the scene's start
  std::filesystem::path checkpoint;      // where checkpoints go; empty: defaultCheckpointPath when any is asked for
  double checkpointEvery = 0;            // simulated s between checkpoints (0: none but the last)
  bool saveLast = false;                 // a checkpoint after the last frame (implied by checkpoint or checkpointEvery)
  gl::Backend backend = gl::Backend::Auto;
  bool debugGl = false;
  bool progress = true;
  std::optional<double> fitBudgetMs;  // --fit-gpu: particles.resolution picked for this budget first (app/fit_gpu.h)
};

// Returns the number of frames written. Throws Error. With job.progress, it says what runs before
// the first frame (runText) and, after the first frame that steps, an estimate of the whole run.
int renderHeadless(const RenderJob& job);

// "dam-break: 262,144 particles, 150 frames at 1280x720" (cells for grid models; no count without one).
std::string runText(const std::string& name, const StageIndicators& shown, int frames, int width, int height);

}  // namespace tidepool
