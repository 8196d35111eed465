// Scene files: JSON data naming the model, its parameters and the default clip to render.
//
//   { "name": "Blank", "description": "...", "model": "blank",
//     "params": { "color": [0.1, 0.2, 0.3] },
//     "clip": { "frames": 90, "fps": 30, "width": 960, "height": 540 } }
//
// A scene may instead state the accuracy it needs and let the engine pick the method:
//   "method": "auto", "accuracy": { "energyDrift": 1e-3 }   (scene/auto/auto.h)
// and a water scene the model too (balls or fluid; its params are a fluid scene's):
//   "model": "auto", "accuracy": { "densityError": 0.01 }
//
// The window, the headless renderer, benchmarks and tests load the same files.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/assets.h"
#include "io/json.h"
#include "scene/auto/auto.h"
#include "scene/scene_params.h"
#include "scene/stage.h"

namespace tidepool {

struct ClipSettings {
  int frames = 90;  // frames rendered by `tidepool render` unless --frames says otherwise
  int fps = 30;     // video playback rate; a frame's simulated time is the model's (Stage::frameSeconds)
  int width = 960, height = 540;
};

struct Scene {
  std::filesystem::path file;  // where it was loaded from
  std::string name, description;
  std::string model = "blank";
  SceneParams params;  // the model's typed parameters, read from "params" at load (scene/scene_params.h)
  ClipSettings clip;
  MethodMode method = MethodMode::Params;  // "auto": pick the method from `accuracy` (scene/auto/auto.h)
  io::Json accuracy;                       // e.g. {"energyDrift": 1e-3}; null when not stated
  std::optional<AutoChoice> autoChoice;    // what "auto" picked (already written into params)
};

void visit(ParamVisitor& v, Scene& scene);  // every key except "params"

using io::findAssetDir;  // assets/ (io/assets.h)

// A path as given, or a bare name such as "blank" looked up as assets/scenes/<name>.json.
std::filesystem::path resolveScenePath(const std::string& nameOrPath);

// Reads the header, then "params" into the model's typed struct, then resolves "method": "auto";
// throws Error naming the file and the key (an unknown model lists the known ones).
Scene loadScene(const std::filesystem::path& file);
// Loads the scene with overrides of its params merged into the file's (a JSON merge patch: e.g.
// --rules sets params.rules), read and validated like the file's own keys.
Scene loadScene(const std::filesystem::path& file, const io::Json& paramOverrides);

// Overrides of a scene's params as the command line gives them, each with the option that set it.
struct ParamOverride {
  std::string origin;  // the option as messages name it, escaped: "--set 'view.mode=bogus'"
  io::Json patch;      // a JSON merge patch of "params": {"view": {"mode": "bogus"}}
};
// loadScene with the overrides merged in order, each tried on top of the file and those before it,
// so that a value the scene refuses is blamed on the option that gave it, not on the file:
//   --set 'view.mode=bogus': params.view.mode = 'bogus' is not one of: balls, water
Scene loadSceneWith(const std::filesystem::path& file, const std::vector<ParamOverride>& overrides);
Scene parseScene(const io::Json& json, const std::string& where);  // `where` names it in messages

// Builds the scene's model's stage from its typed params.
std::unique_ptr<Stage> createStage(const Scene& scene, gl::ShaderLibrary& shaders);

}  // namespace tidepool
