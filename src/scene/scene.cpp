#include "scene/scene.h"

#include "scene/param_json.h"

namespace tidepool {
namespace fs = std::filesystem;

void visit(ParamVisitor& v, Scene& s) {
  v.text({"name", "Name", "shown in the window title"}, s.name);
  v.text({"description", "Description", "what the scene shows"}, s.description);
  v.text({"model", "Model", "blank (more models land with their issues)"}, s.model);
  v.choice({"method", "Method", "params: as the params say; auto: the cheapest measured method meeting accuracy"},
           s.method, kMethodModeNames);
  if (v.beginGroup({"clip", "Clip", "default headless clip"})) {
    v.integer({"frames", "Frames", "frames rendered headless"}, s.clip.frames, 1, 1000000);
    v.integer({"fps", "FPS", "frames per simulated second"}, s.clip.fps, 1, 1000);
    v.integer({"width", "Width", "pixels"}, s.clip.width, 1, 16384);
    v.integer({"height", "Height", "pixels"}, s.clip.height, 1, 16384);
    v.endGroup();
  }
}

fs::path resolveScenePath(const std::string& arg) {
  const fs::path given(arg);
  std::error_code ec;
  if (fs::exists(given, ec) || given.has_parent_path() || given.has_extension()) return given;
  const fs::path named = findAssetDir() / "scenes" / (arg + ".json");
  if (fs::exists(named, ec)) return named;
  std::string known;
  for (const auto& entry : fs::directory_iterator(findAssetDir() / "scenes", ec))
    if (entry.path().extension() == ".json") known += (known.empty() ? "" : ", ") + entry.path().stem().string();
  throw Error("scene '" + arg + "' not found: neither a file nor a name in assets/scenes (known: " + known + ")");
}

namespace {
// The header's keys; "params" and "accuracy" are objects read by the model and by auto.
Scene parseHeader(const io::Json& json, const std::string& where) {
  if (!json.is_object()) throw Error(where + ": a scene must be a JSON object {...}");
  Scene scene;
  io::Json header = json;
  for (auto [key, target] : {std::pair{"params", &scene.params}, std::pair{"accuracy", &scene.accuracy}})
    if (auto it = header.find(key); it != header.end()) {
      *target = *it;
      header.erase(it);
    }
  readParams(
      header, [&](ParamVisitor& v) { visit(v, scene); }, where + ": scene");
  return scene;
}
}  // namespace

Scene parseScene(const io::Json& json, const std::string& where) {
  Scene scene = parseHeader(json, where);
  resolveAutoMethod(scene, where);
  return scene;
}

Scene loadScene(const fs::path& file) { return loadScene(file, io::Json()); }

Scene loadScene(const fs::path& file, const io::Json& overrides) {
  Scene scene = parseHeader(io::readJsonFile(file), file.string());
  scene.file = file;
  if (scene.name.empty()) scene.name = file.stem().string();
  if (overrides.is_object() && !overrides.empty()) {
    if (!scene.params.is_object()) scene.params = io::Json::object();
    for (const auto& [key, value] : overrides.items()) scene.params[key] = value;
  }
  resolveAutoMethod(scene, file.string());  // after the overrides, which it must not silently undo
  return scene;
}

std::unique_ptr<Stage> createStage(const Scene& scene, gl::ShaderLibrary& shaders) {
  std::string known;
  for (const ModelEntry& m : models()) {
    if (scene.model == m.name) return m.create(scene.params, scene.file.string() + ": params", shaders);
    known += (known.empty() ? "" : ", ") + std::string(m.name);
  }
  throw Error(scene.file.string() + ": scene.model = '" + scene.model + "' is not a model (known: " + known + ")");
}

}  // namespace tidepool
