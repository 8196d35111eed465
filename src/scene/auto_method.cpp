#include "scene/auto_method.h"

#include <algorithm>
#include <set>

#include "base/error.h"
#include "base/log.h"
#include "io/assets.h"
#include "scene/auto_models.h"
#include "scene/auto_water.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "scene/water_stage.h"

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

double boundValue(const io::Json& value, const std::string& where) {
  if (!value.is_number()) throw Error(where + ": expected a number, got " + io::excerpt(value));
  const double v = value.get<double>();
  if (!(v > 0 && v <= 1)) throw Error(where + " = " + io::excerpt(value) + " is out of range (0, 1]");
  return v;
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
    if (!source && waterSource(key))
      throw Error(where + "." + key + " is a water metric, for \"model\": \"auto\" (balls or fluid as it needs); a " +
                  scene.model + " scene states " + knownKeys(scene.model));
    if (!source)
      throw Error(where + "." + io::printable(key) + ": unknown key (known for " + scene.model + ": " +
                  knownKeys(scene.model) + ")");
    bounds.push_back({key, boundValue(value, where + "." + key)});
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

// assets/accuracy/<study>.csv; `prefix` (the scene and key) starts the message when it is missing.
io::CsvTable readStudy(const std::string& study, const std::string& prefix = "") {
  const fs::path file = accuracyDir() / (study + ".csv");
  if (!fs::exists(file))
    throw Error(prefix + "accuracy data '" + file.string() + "' is missing: run `tidepool sweep " + study +
                " --ship` (on the GPU machine) to measure and ship it");
  return io::CsvTable(file);
}

Tables readTables(const Source& source) {
  Tables tables;
  for (const char* study : source.studies) tables.studies.emplace_back(study, readStudy(study));
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
void checkConflicts(const io::Json& stated, const Settings& settings, const std::string& where,
                    const std::string& by = "\"method\": \"auto\"", const std::string& orRemove = "the auto method") {
  std::vector<std::string> keys;
  for (const Setting& s : settings)
    if (!s.rescaled) keys.push_back(s.key);
  std::sort(keys.begin(), keys.end());
  for (const std::string& key : keys)
    if (states(stated, key))
      throw Error(where + ": params." + key + " is picked by " + by + "; remove it (or " + orRemove + ")");
}

}  // namespace

std::string AutoChoice::headline() const { return "auto: " + picked + " (" + meets + ")"; }

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
  for (const WaterSource& s : waterSources())
    if (std::find(out.begin(), out.end(), s.study) == out.end()) out.push_back(s.study);
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
  for (const WaterSource& s : waterSources())
    for (const char* column : {"model", "resolution", s.column})
      if (study == s.study && !table.has(column))
        throw Error("--ship: '" + csv.string() + "' has no column '" + column + "' (model auto " + s.key + ")");
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

namespace {

// "model": "auto": the bounds (one study's), the rows of balls and fluid that apply, the cheapest
// that meets them; the scene becomes that model's, with the pick written in.
void resolveModelAuto(Scene& scene, const io::Json& stated, const std::string& sceneWhere) {
  const std::string where = sceneWhere + ": scene.accuracy";
  if (scene.accuracy.is_null() || (scene.accuracy.is_object() && scene.accuracy.empty()))
    throw Error(sceneWhere + ": scene.model = 'auto' needs scene.accuracy, the error the water accepts (" +
                waterKeys() + ")");
  if (!scene.accuracy.is_object())
    throw Error(where + ": expected an object {...}, got " + std::string(scene.accuracy.type_name()));
  std::vector<Bound> bounds;
  std::vector<const WaterSource*> metrics;
  for (const auto& [key, value] : scene.accuracy.items()) {
    const WaterSource* source = waterSource(key);
    if (!source) {
      for (const Source& s : automethod::sources())
        if (key == s.key)
          throw Error(where + "." + key + " is a " + s.model +
                      " metric of \"method\": \"auto\"; a \"model\": \"auto\" scene states " + waterKeys());
      throw Error(where + "." + io::printable(key) + ": unknown key (known for \"model\": \"auto\": " + waterKeys() +
                  ")");
    }
    bounds.push_back({key, boundValue(value, where + "." + key)});
    metrics.push_back(source);
  }
  for (const WaterSource* s : metrics)
    if (std::string(s->study) != metrics[0]->study)
      throw Error(where + ": " + s->key + " (" + s->study + ") and " + metrics[0]->key + " (" + metrics[0]->study +
                  ") are measured by different studies; state bounds of one study");
  const std::string study = metrics[0]->study;
  const io::CsvTable table = readStudy(study, where + "." + metrics[0]->key + ": ");

  // The scene's particles as fluid (as read) and as balls; each pick starts from one of them.
  const FluidSceneParams& asRead = scene.params.as<FluidSceneParams>();
  const SceneParams fluidStart = scene.params;
  const SceneParams ballsStart(BallsSceneParams{asBalls(asRead.model, balls::Params{}), asRead.view});
  std::vector<Candidate> candidates =
      waterCandidates({asRead.model, ballsStart.model<balls::Params>(), *metrics[0], table, where});
  Settings any;  // every key a pick may set: the scene may state none of them (but those rescaled)
  for (const Candidate& c : candidates) any.insert(any.end(), c.settings.begin(), c.settings.end());
  checkConflicts(stated, any, sceneWhere, "\"model\": \"auto\"", "the auto model");
  Selection s;
  try {
    s = selectCheapest(candidates, bounds, where);
  } catch (const Error& e) {
    throw Error(std::string(e.what()) + "; rows: " + (accuracyDir() / (study + ".csv")).string());
  }
  auto picked = [&](const Candidate& c) {
    SceneParams p = c.model == "balls" ? ballsStart : fluidStart;
    write(c.settings, p);
    return p;
  };

  AutoChoice c;
  c.model = s.chosen->model;
  for (std::size_t b = 0; b < bounds.size(); ++b) {
    const std::string sep = b ? ", " : "";
    const std::string error = waterValue(*metrics[b], s.chosen->guaranteed[b]);
    const std::string bound =
        metrics[b]->percent ? formatValue(100.0 * bounds[b].value) + "%" : formatValue(bounds[b].value);
    c.accuracy += sep + metrics[b]->words + " <= " + bound;
    c.errors += sep + error;
    c.meets += sep + error + " <= " + bound;
  }
  c.picked = s.chosen->label;
  c.costMsPerSimS = s.chosen->cost;
  c.mostAccurate = s.mostAccurate->label;
  c.mostAccurateCost = s.mostAccurate->cost;
  c.studies = study;
  c.device = table.text(0, "device");
  c.settings = s.chosen->settings;
  c.mostAccurateParams = picked(*s.mostAccurate);
  scene.params = picked(*s.chosen);
  scene.model = s.chosen->model;
  scene.method = MethodMode::Auto;
  log::info(c.summary());
  scene.autoChoice = c;
}

}  // namespace

void resolveAutoMethod(Scene& scene, const io::Json& stated, const std::string& sceneWhere) {
  if (scene.model == kAutoModel) return resolveModelAuto(scene, stated, sceneWhere);
  const std::string where = sceneWhere + ": scene.accuracy";
  if (scene.method != MethodMode::Auto) {
    if (!scene.accuracy.is_null())
      throw Error(sceneWhere + ": scene.accuracy is read only with \"method\": \"auto\" (add it, or remove accuracy)");
    return;
  }
  bool modelKnown = false;
  for (const Source& s : sources()) modelKnown = modelKnown || scene.model == s.model;
  if (!modelKnown && scene.model == "fluid")
    throw Error(sceneWhere + ": scene.method = 'auto': no measured data for model 'fluid' alone; \"model\": \"auto\" " +
                "picks balls or fluid and its step for water (" + waterKeys() + ")");
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
    c.meets += (b ? ", " : "") + bounds[b].key + " " + formatValue(s.chosen->guaranteed[b]) +
               " <= " + formatValue(bounds[b].value);
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
