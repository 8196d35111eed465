// The options `render` and `run` share: where a run starts and checkpoints (--resume, --checkpoint,
// --checkpoint-every) and what it changes in the scene (--set, --resolution, --fit-gpu, --budget).
// Their values are checked before any work: a bad --set value names that --set, and a resumed run
// takes only the live keys its checkpoint does not fix (scene/checkpoint.h).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/json.h"
#include "scene/scene.h"

namespace tidepool::cli {

struct CheckpointOpts {
  std::string resume, checkpoint;
  double every = 0;
};
void addCheckpointOptions(CLI::App* sub, CheckpointOpts& o);

struct ResolutionOpts {
  double resolution = 0;  // 0: as the scene states
  bool fit = false;
  double budgetMs = 1000.0 / 30.0;
  std::vector<std::string> sets;  // KEY=VALUE
};
void addResolutionOptions(CLI::App* sub, ResolutionOpts& o);

// --set view.mode=water as a merge patch of params: {"view": {"mode": "water"}}. Throws Error.
io::Json setOverride(const std::string& text);

// The overrides in the order they merge: --rules (life), each --set, --resolution.
std::vector<ParamOverride> sceneOverrides(const ResolutionOpts& o, const std::string& rules);
io::Json merged(const std::vector<ParamOverride>& overrides);  // one patch of them all (null: none)

// Loads the scene with the overrides, refusing a bad value by its option; with --resume, refuses
// --fit-gpu and every override of a key the checkpoint fixes, on one line naming the option, the
// key and the checkpoint. Throws Error; returns the scene.
Scene checkSceneOptions(const std::string& scene, const std::vector<ParamOverride>& overrides, const ResolutionOpts& o,
                        const std::string& resume);

}  // namespace tidepool::cli
