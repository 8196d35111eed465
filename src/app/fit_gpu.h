// `--fit-gpu`: the finest resolution (particles.resolution) of a water scene whose frame, the
// steps of one frame of simulated time and its render, stays within a budget on this device.
// Measured, not guessed: each trial builds the scene at a resolution, runs a few frames after a
// warm-up and takes the median wall time with glFinish around each frame. The next trial scales
// the resolution by (budget / measured)^(1/4) (a frame's cost grows as R³ particles times R
// substeps), then bisects between the finest that fitted and the coarsest that did not.
//
//   tidepool render dam-break --fit-gpu --budget 33    ->  "fit: resolution 5.9 (1,010,000 balls) 31.8 ms"
//
// The frames measured are the scene's first ones: a scene that gets dearer later (a splash that
// packs more contacts) can exceed the budget then.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "gl/shader_library.h"
#include "io/json.h"

namespace tidepool {

struct FitOptions {
  double budgetMs = 1000.0 / 30.0;  // step + render of one frame, wall ms
  int width = 960, height = 540;    // the render target measured
  double maxResolution = 64;        // the finest tried
  int frames = 5;                   // measured per trial (after two warm-up frames)
  int maxTrials = 8;
};

struct FitTrial {
  double resolution = 1;
  std::size_t particles = 0;  // what the scene built at it (0: refused)
  double frameMs = 0;         // median wall ms per frame (refused: 0)
  bool fits = false;          // frameMs <= the budget
  std::string refused;        // why it could not be built (a limit named by the model), else empty
};

struct FitResult {
  double resolution = 0;  // the finest trial that fitted; 0: none did
  std::vector<FitTrial> trials;
  std::string table() const;  // one line a trial, for the log
};

// Trials of `scene` (a path) with `overrides` merged into its params, particles.resolution set per
// trial. Throws Error for a scene that is not balls or fluid water.
FitResult fitResolution(const std::filesystem::path& scene, const io::Json& overrides, gl::ShaderLibrary& shaders,
                        const FitOptions& options);

// `overrides` with particles.resolution set to the fit's pick; throws Error with one line when no
// trial fitted (the coarsest tried, its ms and the budget).
io::Json withFittedResolution(const FitResult& fit, const io::Json& overrides, double budgetMs);

// The whole of --fit-gpu for render and run: the trials (logged as a table), then `overrides` with
// the pick, as withFittedResolution.
io::Json fitOverrides(const std::filesystem::path& scene, const io::Json& overrides, gl::ShaderLibrary& shaders,
                      const FitOptions& options);

}  // namespace tidepool
