// Checkpoints of a running scene: the stage's parameters as they are now (JSON, so live edits
// survive) and all the state a later step reads (Stage::visitState: the model's clock, counters,
// RNG and GPU buffers, the divergence watch's phase, the stage's own), in the versioned file of
// io/checkpoint_file.h, written atomically. Restoring into a fresh stage of the same scene and
// stepping on equals the uninterrupted run bit for bit.
//
//   saveCheckpoint(*stage, scene, "run.ckpt");          // after a frame
//   auto fresh = createStage(scene, shaders);
//   loadCheckpoint(*fresh, scene, "run.ckpt");          // throws Error "run.ckpt: ..." naming the problem
//
// Periodic saves (`--checkpoint-every`, the window's autosave) follow a CheckpointSchedule.
//
// A checkpoint also holds the number of the frame it is, as `render` numbers them (frame i shows
// the state after i frame steps from t = 0), so that a resumed render goes on with the next number.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/checkpoint_file.h"
#include "scene/scene.h"
#include "scene/stage.h"

namespace tidepool {

// At most this frame number in a checkpoint: a resumed run's numbers stay well inside an int.
inline constexpr std::uint64_t kMaxCheckpointFrame = 1'000'000'000;

// The checkpoint of `stage`, a stage of `scene`, shown as frame `frame`. Throws Error when the
// model's state is diverged.
io::Checkpoint captureCheckpoint(Stage& stage, const Scene& scene, std::uint64_t frame = 0);
// captureCheckpoint, written atomically to `file` (a previous checkpoint there stays whole until
// the new one is complete). Throws Error.
void saveCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file, std::uint64_t frame = 0);

// Puts `checkpoint` into `stage`, a freshly created stage of `scene`: its model must be the
// scene's; its parameters override the scene file's; every entry must fit the state at those
// parameters; the state as loaded must pass the model's health check and, for balls and fluid,
// water::kMaxPerDiameterCube (sim/water/cell_load.h). Errors start with `where` (the file).
// After a failure the stage is half restored: reset it or make a new one. Returns the checkpoint's
// frame number (0 for a file that holds none, from a build before frames were numbered).
std::uint64_t restoreCheckpoint(Stage& stage, const Scene& scene, const io::Checkpoint& checkpoint,
                                const std::string& where);
std::uint64_t loadCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file);  // read, restore

// Parameters set on top of a checkpoint's (`--set view.mode=water` with `--resume`): only live
// ones, which the window's panel edits mid-run (the view, and the physics: engine, walls, ...);
// not a model's ModelEntry::stateKeys (particle counts, size, domain), which the state fixes.
struct StateKeyHit {
  std::string key;   // the key set, dotted: "particles.resolution"
  std::string what;  // what it shapes: "the particles' count, size, domain and initial water"
};
// The first key of `overrides` (scene params, a JSON merge patch) that `model` (a model's name)
// counts as state; nullopt when all are live.
std::optional<StateKeyHit> stateKeyIn(const std::string& model, const io::Json& overrides);
// loadCheckpoint into `stage`, freshly built from `scene` as loaded with `overrides`, and then the
// keys of `overrides` set to the values the stage was built with (a refined scene's engine.dt is
// refined: as a fresh run would take them). Throws Error for a state key (stateKeyIn).
std::uint64_t loadCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file,
                             const io::Json& overrides);

// When periodic checkpoints are due: at every multiple of `every` simulated seconds (0: never),
// counted from t = 0 so that a resumed run keeps the cadence of the run it continues.
class CheckpointSchedule {
 public:
  explicit CheckpointSchedule(double every = 0, double startTime = 0) { reset(every, startTime); }
  void reset(double every, double time);  // a new period (the window's parameter), from `time`
  bool due(double time);                  // true once per multiple of `every` reached; advances to the next
  double every() const { return m_every; }
  double next() const { return m_next; }  // simulated s of the next save (infinity: off)

 private:
  double m_every = 0, m_next = 0;
};

// Where checkpoints go when no --checkpoint path is given: beside the output, "out/dam" ->
// "out/dam.ckpt", "clip.mp4" -> "clip.ckpt"; with neither, "<scene name>.ckpt" here.
std::filesystem::path defaultCheckpointPath(const std::filesystem::path& outDir, const std::filesystem::path& video,
                                            const std::filesystem::path& sceneFile);

}  // namespace tidepool
