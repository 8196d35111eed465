// Long runs: a scene stepped headless for many frames, as the window and `tidepool
// render` step it (one Stage::step per frame, the divergence watch on), and sampled
// every few frames for what only a long run shows: the process's resident memory
// (/proc/self/statm), the particles still finite and inside the walls, and the model's energy.
// Each sample also renders the stage once (a small target), so that the views soak too.
//
//   SoakLimits limits;                                   // warm-up, RSS tolerance, energy factor
//   const SoakResult r = soak(scene, shaders, {.steps = 100000, .every = 5000}, print);
//   const auto failures = judgeSoak(r.samples, limits);  // empty: it held
//
// judgeSoak, on the samples after the warm-up (the first `warmup` of the steps: shader builds,
// the driver's caches and the allocator's pools settle there):
//   memory   RSS grows by at most rssGrowthMiB from the first sample after warm-up to the last
//   count    every sample holds as many particles (finite, inside the walls) as the model has,
//            and the model as many as at the start
//   NaN      none (the count above), and the divergence watch reported nothing (soak() throws)
//   energy   finite, and at most energyFactor × the largest energy seen up to the first sample
//            after warm-up (that sample included: a model that starts at rest has moved by then)
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gl/shader_library.h"
#include "scene/scene.h"

namespace tidepool::sweep {

struct SoakSample {
  long step = 0;           // frames stepped
  double time = 0;         // simulated s
  double wallSeconds = 0;  // since the first step
  double rssMiB = 0;       // resident set size of the process
  std::size_t count = 0;   // the model's particles (ripples: cells)
  std::size_t held = 0;    // of them finite, and inside the walls for particles
  double energy = 0;       // SoakResult::energyName says which
};

struct SoakResult {
  std::string energyName;  // what `energy` is, with units ("kinetic + potential (J)")
  std::vector<SoakSample> samples;
};

struct SoakRun {
  long steps = 100000;  // frames (one Stage::step each)
  long every = 0;       // frames between samples; 0: steps / 20
  int renderWidth = 160, renderHeight = 90;
};

struct SoakLimits {
  double warmup = 0.1;        // fraction of the steps before the baselines are taken
  double rssGrowthMiB = 4.0;  // most RSS growth after warm-up (docs/RELIABILITY.md says why 4)
  double energyFactor = 10;   // energy at most this × the warm-up's largest
};

// Steps and samples (the first at step 0, the last at `steps`), calling `onSample` as each is
// taken. Throws Error for a model it cannot read (blank) and when the divergence watch reports
// (the message says at which step).
SoakResult soak(const Scene& scene, gl::ShaderLibrary& shaders, const SoakRun& run,
                const std::function<void(const SoakSample&)>& onSample = {});

// What failed, one line each (empty: the run held); see the top of this file.
std::vector<std::string> judgeSoak(const std::vector<SoakSample>& samples, const SoakLimits& limits);

double residentMiB();  // of this process, from /proc/self/statm (0 where there is none)

}  // namespace tidepool::sweep
