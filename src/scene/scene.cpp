#include "scene/scene.h"

#include <algorithm>

#include "io/echo.h"
#include "scene/param_json.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxShownName = 80;  // characters of a scene's name: control bytes escaped

std::string modelNames() {
  std::string names;
  for (const ModelEntry& m : models()) names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names + ", " + kAutoModel;
}

// "model": "auto" reads a fluid scene's params (the balls' follow from them, scene/auto/auto.h).
const ModelEntry& modelNamed(const std::string& name, const std::string& where) {
  const std::string model = name == kAutoModel ? "fluid" : name;
  for (const ModelEntry& m : models())
    if (model == m.name) return m;
  throw Error(where + ": scene.model = '" + io::printable(name) + "' is not a model (known: " + modelNames() + ")");
}

}  // namespace

void visit(ParamVisitor& v, Scene& s) {
  static const std::string models =
      "the model the scene runs: " + modelNames() + " (water, balls or fluid as the accuracy needs)";
  v.text({"name", "Name", "shown in the window title"}, s.name);
  v.text({"description", "Description", "what the scene shows"}, s.description);
  v.text({"model", "Model", models.c_str()}, s.model);
  v.choice({"method", "Method", "params: as the params say; auto: the cheapest measured method meeting accuracy"},
           s.method, kMethodModeNames);
  if (v.beginGroup({"clip", "Clip", "default headless clip"})) {
    v.integer({"frames", "Frames", "frames rendered headless"}, s.clip.frames, 1, 1000000);
    v.integer({"fps", "FPS", "video frames per second of playback (the model sets a frame's simulated time)"},
              s.clip.fps, 1, 1000);
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
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(findAssetDir() / "scenes", ec))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  std::string known;
  for (const std::string& name : names) known += (known.empty() ? "" : ", ") + name;
  throw Error("scene '" + io::printable(arg) +
              "' not found: neither a file nor a name in assets/scenes (known: " + known + ")");
}

namespace {
// A water scene states particles.resolution R beside its own spacing (or --resolution sets it): the
// params read hold that spacing until here, then are refined R times, after method
// auto, which picks for the scene as measured. The params keep R as the record of what was done.
// (refine() is balls::refine for the balls, water::refine for the fluid.)
template <class P>
bool refineStated(SceneParams& params, const std::string& where) {
  if (!params.holds<P>()) return false;
  P& p = params.model<P>();
  float& record = p.resolution;
  const double stated = record;
  if (stated == 1.0) return true;
  record = 1.0f;
  try {
    refine(p, stated);
  } catch (const Error& e) {
    throw Error(where + ": params.particles." + e.what());
  }
  return true;
}

void applyResolution(Scene& scene, const std::string& where) {
  if (!refineStated<balls::Params>(scene.params, where)) refineStated<fluid::Params>(scene.params, where);
}

// The header's keys; then "params" (with the overrides merged in) read once into the model's typed
// struct; then method auto, which edits that struct and reads "params" as written only to refuse
// keys it would override.
Scene readScene(const io::Json& json, const std::string& where, const io::Json& overrides) {
  if (!json.is_object()) throw Error(where + ": a scene must be a JSON object {...}");
  Scene scene;
  io::Json header = json, params;
  for (auto [key, target] : {std::pair{"params", &params}, std::pair{"accuracy", &scene.accuracy}})
    if (auto it = header.find(key); it != header.end()) {
      *target = *it;
      header.erase(it);
    }
  readParams(
      header, [&](ParamVisitor& v) { visit(v, scene); }, where + ": scene");
  scene.name = io::printable(scene.name, kMaxShownName);  // shown in titles, progress lines and errors
  // After the header's own checks, so a misspelled "modle" is named as such.
  if (!json.contains("model")) throw Error(where + ": scene.model is missing: give one of " + modelNames());
  if (scene.model == kAutoModel && scene.method == MethodMode::Params && header.contains("method"))
    throw Error(where + ": scene.method = 'params' contradicts scene.model = 'auto', which picks the method too " +
                "(remove method)");
  if (overrides.is_object() && !overrides.empty()) {
    if (!params.is_object()) params = io::Json::object();
    params.merge_patch(overrides);
  }
  scene.params = modelNamed(scene.model, where).parse(params, where + ": params");
  resolveAuto(scene, params, where);  // after the overrides, which it must not silently undo
  applyResolution(scene, where);
  return scene;
}
}  // namespace

Scene parseScene(const io::Json& json, const std::string& where) { return readScene(json, where, io::Json()); }

Scene loadScene(const fs::path& file) { return loadScene(file, io::Json()); }

namespace {
Scene fromFile(Scene scene, const fs::path& file) {
  scene.file = file;
  if (scene.name.empty()) scene.name = io::printable(file.stem().string(), kMaxShownName);
  return scene;
}
}  // namespace

Scene loadScene(const fs::path& file, const io::Json& overrides) {
  return fromFile(readScene(io::readJsonFile(file), io::shownPath(file), overrides), file);
}

Scene loadSceneWith(const fs::path& file, const std::vector<ParamOverride>& overrides) {
  const io::Json json = io::readJsonFile(file);
  io::Json merged = io::Json::object();
  Scene scene = readScene(json, io::shownPath(file), merged);  // the file's own faults name the file
  for (const ParamOverride& o : overrides) {
    merged.merge_patch(o.patch);
    scene = readScene(json, o.origin, merged);
  }
  return fromFile(std::move(scene), file);
}

std::unique_ptr<Stage> createStage(const Scene& scene, gl::ShaderLibrary& shaders) {
  const std::string where = io::shownPath(scene.file);
  return modelNamed(scene.model, where).create(scene.params, where + ": params", shaders);
}

}  // namespace tidepool
