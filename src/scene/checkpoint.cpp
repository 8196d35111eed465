#include "scene/checkpoint.h"

#include <cmath>
#include <limits>

#include "base/error.h"
#include "io/json.h"
#include "scene/param_json.h"
#include "sim/model_state.h"
#include "sim/water/cell_load.h"
#include "sim/water/particle_water.h"

namespace tidepool {
namespace {
// Simulated times are sums of frame steps (1/30 s ten times is not exactly 1/3): a save is due
// within this fraction of a period before its time.
constexpr double kDueSlack = 1e-9;
constexpr const char* kFrameEntry = "clip.frame";  // u64, the frame number (see checkpoint.h)

// Visits a stage's state as a save does, keeping nothing: a model first runs its health check on
// the state as it is and refuses an unhealthy one through fail(), which names the file.
class Judge final : public sim::StateVisitor {
 public:
  explicit Judge(std::string where) : m_where(std::move(where)) {}
  bool loading() const override { return false; }
  void clock(double&, std::uint64_t&) override {}
  void bytes(const char*, void*, std::size_t) override {}
  void text(const char*, std::string&, std::size_t) override {}
  void buffer(const char*, gl::Buffer&, std::size_t) override {}
  [[noreturn]] void fail(const std::string& what) const override { throw Error(m_where + ": " + what); }

 private:
  std::string m_where;
};

// A loaded state is judged as a saved one is (NaN, out of the domain: the model's health check),
// and particle water may not crowd one cube of its diameter past water::kMaxPerDiameterCube.
void judgeLoadedState(Stage& stage, const std::string& where) {
  Judge judge(where);
  stage.visitState(judge);
  if (const auto* water = dynamic_cast<const water::ParticleWater*>(stage.model()))
    if (std::optional<std::string> crowded = water::overcrowded(*water)) throw Error(where + ": " + *crowded);
}
}  // namespace

io::Checkpoint captureCheckpoint(Stage& stage, const Scene& scene, std::uint64_t frame) {
  stage.flushChecks();  // the watch's check in flight is judged: a checkpoint never holds one
  io::Checkpoint c;
  c.model = scene.model;
  c.scene = scene.file.string();
  sim::StateSaver saver(c);
  stage.visitSetupState(saver);
  c.params = writeParams([&](ParamVisitor& v) { stage.visitParams(v); }).dump();
  stage.visitState(saver);
  saver.value(kFrameEntry, frame);
  return c;
}

void saveCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file, std::uint64_t frame) {
  const io::Checkpoint c = captureCheckpoint(stage, scene, frame);
  io::writeFileAtomically(file, io::encodeCheckpoint(c));
}

std::uint64_t restoreCheckpoint(Stage& stage, const Scene& scene, const io::Checkpoint& c, const std::string& where) {
  if (c.model != scene.model)
    throw Error(where + " is a " + io::printable(c.model) + " checkpoint" +
                (c.scene.empty() ? "" : " (of " + io::printable(c.scene, 200) + ")") + ", the scene runs " +
                scene.model);
  sim::StateLoader loader(c, where);
  std::uint64_t frame = 0;
  try {
    stage.visitSetupState(loader);
    readParams(
        io::parseJson(c.params, where + ": params"), [&](ParamVisitor& v) { stage.visitParams(v); },
        where + ": params");
    stage.reset();
    stage.visitState(loader);
    if (c.find(kFrameEntry)) loader.value(kFrameEntry, frame);
    if (frame > kMaxCheckpointFrame)
      loader.fail(std::string("entry '") + kFrameEntry + "' = " + std::to_string(frame) + " is more than " +
                  std::to_string(kMaxCheckpointFrame) + " frames");
    loader.finish();
    judgeLoadedState(stage, where);
  } catch (const Error& e) {  // what a model built at these parameters says (too many particles, ...)
    if (std::string(e.what()).rfind(where, 0) == 0) throw;
    throw Error(where + ": " + e.what());
  }
  return frame;
}

std::uint64_t loadCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file) {
  return restoreCheckpoint(stage, scene, io::readCheckpointFile(file), file.string());
}

namespace {
// Where a merge patch sets values: {"view": {"mode": "water", "camera": {"yaw": 1}}} -> /view/mode,
// /view/camera/yaw. An array or any other value is one place, as a merge patch replaces it whole.
void leaves(const io::Json& patch, const io::Json::json_pointer& at, std::vector<io::Json::json_pointer>& out) {
  if (!patch.is_object() || (patch.empty() && !at.empty())) {
    if (!at.empty()) out.push_back(at);
    return;
  }
  for (const auto& [key, value] : patch.items()) leaves(value, at / key, out);
}
std::vector<io::Json::json_pointer> leaves(const io::Json& patch) {
  std::vector<io::Json::json_pointer> out;
  leaves(patch, io::Json::json_pointer(), out);
  return out;
}

std::string dotted(io::Json::json_pointer at) {
  std::string key;
  for (; !at.empty(); at.pop_back()) key = at.back() + (key.empty() ? "" : "." + key);
  return key;
}

bool under(const std::string& key, const std::string& prefix) {
  return key == prefix ||
         (key.size() > prefix.size() && key.compare(0, prefix.size(), prefix) == 0 && key[prefix.size()] == '.');
}
}  // namespace

std::optional<StateKeyHit> stateKeyIn(const std::string& model, const io::Json& overrides) {
  for (const ModelEntry& m : models())
    if (model == m.name)
      for (const io::Json::json_pointer& at : leaves(overrides))
        for (const StateKey& s : m.stateKeys)
          if (const std::string key = dotted(at); under(key, s.key)) return StateKeyHit{key, s.what};
  return std::nullopt;
}

std::uint64_t loadCheckpoint(Stage& stage, const Scene& scene, const std::filesystem::path& file,
                             const io::Json& overrides) {
  const std::string where = file.string();
  if (const std::optional<StateKeyHit> hit = stateKeyIn(scene.model, overrides))
    throw Error(where + ": params." + io::printable(hit->key) + " changes the simulation state (" + hit->what +
                "): a resumed run cannot set it");
  const io::Json built = writeParams([&](ParamVisitor& v) { stage.visitParams(v); });
  const std::uint64_t frame = loadCheckpoint(stage, scene, file);
  io::Json live = io::Json::object();
  for (const io::Json::json_pointer& at : leaves(overrides)) {
    if (!built.contains(at))
      throw Error(where + ": params." + io::printable(dotted(at)) + " is not a parameter of the running " +
                  scene.model + " stage: a resumed run cannot set it");
    live[at] = built[at];
  }
  readParams(
      live, [&](ParamVisitor& v) { stage.visitParams(v); }, where + ": params");
  return frame;
}

void CheckpointSchedule::reset(double every, double time) {
  m_every = every > 0 && std::isfinite(every) ? every : 0;
  m_next =
      m_every > 0 ? (std::floor(time / m_every + kDueSlack) + 1) * m_every : std::numeric_limits<double>::infinity();
}

bool CheckpointSchedule::due(double time) {
  if (m_every <= 0 || time < m_next - kDueSlack * m_every) return false;
  reset(m_every, time);
  return true;
}

std::filesystem::path defaultCheckpointPath(const std::filesystem::path& outDir, const std::filesystem::path& video,
                                            const std::filesystem::path& sceneFile) {
  if (!outDir.empty()) {
    std::filesystem::path dir = outDir;
    if (!dir.has_filename()) dir = dir.parent_path();  // "out/dam/" -> "out/dam"
    return dir.string() + ".ckpt";
  }
  if (!video.empty()) return std::filesystem::path(video).replace_extension(".ckpt");
  return sceneFile.stem().string() + ".ckpt";
}

}  // namespace tidepool
