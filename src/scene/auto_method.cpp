#include "scene/auto_method.h"

#include <algorithm>
#include <set>

#include "base/error.h"
#include "base/log.h"
#include "io/assets.h"
#include "scene/auto_models.h"
#include "scene/scene.h"

namespace tidepool {
namespace fs = std::filesystem;
using namespace automethod;

namespace {

std::string knownKeys(const std::string& model) {
  std::string out;
  for (const Source& s : sources())
    if (model == s.model) out += (out.empty() ? "" : ", ") + std::string(s.key);
  for (const std::string& k : extraKeys(model)) out += ", " + k;
  return out;
}

std::vector<Bound> readBounds(const Scene& scene, const std::string& where, std::vector<const Source*>& metrics) {
  std::vector<Bound> bounds;
  const std::vector<std::string> extras = extraKeys(scene.model);
  for (const auto& [key, value] : scene.accuracy.items()) {
    if (std::find(extras.begin(), extras.end(), key) != extras.end()) continue;  // read by the model
    const Source* source = nullptr;
    const Source* elsewhere = nullptr;
    for (const Source& s : sources())
      if (key == s.key) (scene.model == s.model ? source : elsewhere) = &s;
    if (!source && elsewhere)
      throw Error(where + "." + key + " is a " + elsewhere->model + " metric; a " + scene.model + " scene states " +
                  knownKeys(scene.model));
    if (!source)
      throw Error(where + "." + key + ": unknown key (known for " + scene.model + ": " + knownKeys(scene.model) + ")");
    if (!value.is_number()) throw Error(where + "." + key + ": expected a number, got " + value.dump());
    const double v = value.get<double>();
    if (!(v > 0 && v <= 1)) throw Error(where + "." + key + " = " + value.dump() + " is out of range (0, 1]");
    bounds.push_back({key, v});
    metrics.push_back(source);
  }
  if (bounds.empty())
    throw Error(where + ": states no accuracy bound (known for " + scene.model + ": " + knownKeys(scene.model) + ")");
  for (const Source* s : metrics)
    if (s->studies != metrics[0]->studies)
      throw Error(where + ": " + s->key + " and " + metrics[0]->key +
                  " are measured by different studies; state bounds of one study");
  return bounds;
}

Tables readTables(const Source& source) {
  Tables tables;
  for (const char* study : source.studies) {
    const fs::path file = accuracyDir() / (std::string(study) + ".csv");
    const std::string name = study;
    if (!fs::exists(file))
      throw Error("accuracy data '" + file.string() + "' is missing: run `tidepool sweep " + study +
                  " --ship` (on the GPU machine) to measure and ship it");
    tables.studies.emplace_back(name, io::CsvTable(file));
  }
  return tables;
}

// Whether the scene's "params" object as written states `key` ("engine.dt"): the typed params
// cannot tell a stated value from a default.
bool states(const io::Json& params, const std::string& key) {
  const io::Json* at = &params;
  for (std::size_t start = 0;;) {
    const std::size_t dot = key.find('.', start);
    const std::string name = key.substr(start, dot - start);
    if (!at->is_object() || !at->contains(name)) return false;
    at = &at->at(name);
    if (dot == std::string::npos) return true;
    start = dot + 1;
  }
}

// A key the pick sets that the scene sets too (other than the ones the pick rescales) would be
// silently overridden: refuse it instead, naming the first in key order.
void checkConflicts(const io::Json& stated, const Settings& settings, const std::string& where) {
  std::vector<std::string> keys;
  for (const Setting& s : settings)
    if (!s.rescaled) keys.push_back(s.key);
  std::sort(keys.begin(), keys.end());
  for (const std::string& key : keys)
    if (states(stated, key))
      throw Error(where + ": params." + key + " is picked by \"method\": \"auto\"; remove it (or the auto method)");
}

}  // namespace

std::string AutoChoice::summary() const {
  return "auto: picked " + picked + " (" + errors + " for " + accuracy + ", cost " + formatValue(costMsPerSimS) +
         " ms per simulated s; most accurate, " + mostAccurate + ", costs " + formatValue(mostAccurateCost) +
         "; data: " + studies + " on " + device + ")";
}

fs::path accuracyDir() { return io::findAssetDir() / "accuracy"; }

namespace {
bool readsFrom(const Source& s, const std::string& study) {
  return std::find(s.studies.begin(), s.studies.end(), study) != s.studies.end();
}
}  // namespace

std::vector<std::string> shippedStudies() {
  std::vector<std::string> out;
  for (const Source& s : sources()) {
    for (const char* study : s.studies)
      if (std::find(out.begin(), out.end(), study) == out.end()) out.push_back(study);
  }
  return out;
}

fs::path shipStudy(const std::string& study, const fs::path& csv) {
  const std::vector<std::string> shipped = shippedStudies();
  if (std::find(shipped.begin(), shipped.end(), study) == shipped.end()) {
    std::string list;
    for (const std::string& s : shipped) list += (list.empty() ? "" : ", ") + s;
    throw Error("--ship: method auto reads no data from " + study + " (it reads " + list + ")");
  }
  const io::CsvTable table(csv);
  for (const char* column : {"method", "dt", "gpu_ms_per_sim_s", "stable", "device"})
    if (!table.has(column)) throw Error("--ship: '" + csv.string() + "' has no column '" + column + "'");
  for (const Source& s : sources())
    if (readsFrom(s, study) && !table.has(s.column))
      throw Error("--ship: '" + csv.string() + "' has no column '" + s.column + "' (" + s.model + " " + s.key + ")");
  const std::string device = table.text(0, "device");
  if (device.find("llvmpipe") != std::string::npos || device.find("softpipe") != std::string::npos)
    log::warn("--ship: " + study + " was measured on " + device +
              ": its costs are development figures; ship the GPU machine's run");
  const fs::path dest = accuracyDir() / (study + ".csv");
  std::error_code ec;
  fs::create_directories(dest.parent_path(), ec);
  if (fs::exists(dest) && fs::equivalent(dest, csv, ec)) return dest;
  if (!fs::copy_file(csv, dest, fs::copy_options::overwrite_existing, ec))
    throw Error("--ship: cannot copy '" + csv.string() + "' to '" + dest.string() + "': " + ec.message());
  return dest;
}

void resolveAutoMethod(Scene& scene, const io::Json& stated, const std::string& sceneWhere) {
  const std::string where = sceneWhere + ": scene.accuracy";
  if (scene.method != MethodMode::Auto) {
    if (!scene.accuracy.is_null())
      throw Error(sceneWhere + ": scene.accuracy is read only with \"method\": \"auto\" (add it, or remove accuracy)");
    return;
  }
  bool modelKnown = false;
  for (const Source& s : sources()) modelKnown = modelKnown || scene.model == s.model;
  if (!modelKnown)
    throw Error(sceneWhere + ": scene.method = 'auto': no measured data for model '" + scene.model +
                "' (auto works for balls, ripples and swarm)");
  if (scene.accuracy.is_null() || (scene.accuracy.is_object() && scene.accuracy.empty()))
    throw Error(sceneWhere + ": scene.method = 'auto' needs scene.accuracy, the error the scene accepts (" +
                scene.model + ": " + knownKeys(scene.model) + ")");
  if (!scene.accuracy.is_object())
    throw Error(where + ": expected an object {...}, got " + std::string(scene.accuracy.type_name()));
  std::vector<const Source*> metrics;
  const std::vector<Bound> bounds = readBounds(scene, where, metrics);
  const Tables tables = readTables(*metrics[0]);
  const ModelInput in{scene.params, scene.accuracy, metrics, tables, where};
  std::vector<Candidate> candidates = scene.model == "swarm"     ? swarmCandidates(in)
                                      : scene.model == "ripples" ? ripplesCandidates(in)
                                                                 : ballsCandidates(in);
  const Selection s = selectCheapest(candidates, bounds, where);
  checkConflicts(stated, s.chosen->settings, sceneWhere);
  const SceneParams asStated = scene.params;
  write(s.chosen->settings, scene.params);

  AutoChoice c;
  std::set<std::string> devices;
  for (std::size_t b = 0; b < bounds.size(); ++b) {
    c.accuracy += (b ? ", " : "") + bounds[b].key + " <= " + formatValue(bounds[b].value);
    c.errors += (b ? ", " : "") + bounds[b].key + " " + formatValue(s.chosen->guaranteed[b]);
  }
  for (const auto& [name, table] : tables.studies) {
    c.studies += (c.studies.empty() ? "" : ", ") + name;
    if (devices.insert(table.text(0, "device")).second)
      c.device += (c.device.empty() ? "" : ", ") + table.text(0, "device");
  }
  c.picked = s.chosen->label;
  c.costMsPerSimS = s.chosen->cost;
  c.mostAccurate = s.mostAccurate->label;
  c.mostAccurateCost = s.mostAccurate->cost;
  c.settings = s.chosen->settings;
  c.mostAccurateParams = asStated;
  write(s.mostAccurate->settings, c.mostAccurateParams);
  log::info(c.summary());
  scene.autoChoice = c;
}

}  // namespace tidepool
