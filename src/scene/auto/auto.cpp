#include "scene/auto/auto.h"

#include <algorithm>
#include <set>

#include "base/error.h"
#include "base/log.h"
#include "io/assets.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "scene/water_stage.h"

namespace tidepool {
namespace fs = std::filesystem;
using namespace automethod;

const std::vector<Metric>& automethod::metrics() {
  static const std::vector<Metric> table = {
      // max |dE|/s over 10 orbits of the reference orbit, relative to the attractor strength
      {"swarm", "energyDrift", "energy_error", {"swarm-orbit", "swarm-precision"}},
      // |c_measured/c - 1| of a plane wave at the scene's cells per wavelength
      {"ripples", "phaseError", "phase_error", {"ripples-dispersion"}},
      // largest overlap of two balls in the settled water block, fraction of r
      {"balls", "maxOverlap", "max_overlap_r", {"balls-settle"}},
      // |energy of the settled block - the rigid stack's| per ball, in units of m g r
      {"balls", "energyDrift", "energy_drift", {"balls-settle"}},
      // |e_measured/e - 1| of one spring-dashpot bounce
      {"balls", "restitutionError", "restitution_error", {"balls-restitution"}},
      // mean |rho/rho0 - 1| over the particles of the study's water, over its run (rows of balls and fluid)
      {"water", "densityError", "density_error_mean", {"fluid-density"}, "density error", true},
      // RMS error of the dam break's surge front against the finest run of the same model
      {"water", "frontError", "front_error", {"water-front"}, "front error"},
  };
  return table;
}

std::string automethod::knownKeys(const std::string& model) {
  std::string out;
  for (const Metric& m : metrics())
    if (model == m.model) out += (out.empty() ? "" : ", ") + m.key;
  return out + (model == "ripples" ? ", wavelength, wavelengthCells" : "");  // they describe the scene's waves
}

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The bounds scene.accuracy states for `model` (a Metric's), with their metrics, all of one study.
std::vector<Bound> readBounds(const io::Json& accuracy, const std::string& model, const std::string& where,
                              std::vector<const Metric*>& read) {
  const std::string name = model == "water" ? "\"model\": \"auto\"" : model;
  std::vector<Bound> bounds;
  for (const auto& [key, value] : accuracy.items()) {
    if (model == "ripples" && (key == "wavelength" || key == "wavelengthCells")) continue;  // read with the rows
    const Metric* metric = nullptr;
    std::string others;  // the models whose metric `key` is
    for (const Metric& m : metrics())
      if (key == m.key && model == m.model)
        metric = &m;
      else if (key == m.key)
        others += (others.empty() ? "" : " and ") + m.model;
    if (!metric && !others.empty())
      throw Error(where + "." + key + " is a " + others + " metric" +
                  (others == "water"  ? ", for \"model\": \"auto\" (balls or fluid as it needs)"
                   : model == "water" ? " of \"method\": \"auto\""
                                      : "") +
                  "; a " + name + " scene states " + knownKeys(model));
    if (!metric)
      throw Error(where + "." + io::printable(key) + ": unknown key (known for " + name + ": " + knownKeys(model) +
                  ")");
    if (!value.is_number()) throw Error(where + "." + key + ": expected a number, got " + io::excerpt(value));
    if (!(value.get<double>() > 0 && value.get<double>() <= 1))
      throw Error(where + "." + key + " = " + io::excerpt(value) + " is out of range (0, 1]");
    bounds.push_back({key, value.get<double>()});
    read.push_back(metric);
  }
  if (bounds.empty())
    throw Error(where + ": states no accuracy bound (known for " + name + ": " + knownKeys(model) + ")");
  for (const Metric* m : read)
    if (m->studies != read[0]->studies)
      throw Error(where + ": " + m->key + " (" + join(m->studies) + ") and " + read[0]->key + " (" +
                  join(read[0]->studies) + ") are measured by different studies; state bounds of one study");
  return bounds;
}

fs::path studyFile(const std::string& study) { return accuracyDir() / (study + ".csv"); }

// Whether the scene's "params" object as written states `key` ("engine.dt"): the typed params
// cannot tell a stated value from a default.
bool states(const io::Json& params, std::string key) {
  std::replace(key.begin(), key.end(), '.', '/');
  return params.contains(io::Json::json_pointer("/" + key));
}

// A key the pick sets that the scene sets too (other than the ones the pick rescales) would be
// silently overridden: refuse it instead, naming the first in key order.
void checkConflicts(const io::Json& stated, const Settings& settings, const std::string& where, bool modelAuto) {
  std::vector<std::string> keys;
  for (const Setting& s : settings)
    if (!s.rescaled) keys.push_back(s.key);
  std::sort(keys.begin(), keys.end());
  for (const std::string& key : keys)
    if (states(stated, key))
      throw Error(where + ": params." + key + " is picked by " +
                  (modelAuto ? "\"model\": \"auto\"; remove it (or the auto model)"
                             : "\"method\": \"auto\"; remove it (or the auto method)"));
}

}  // namespace

std::string AutoChoice::headline() const { return "auto: " + picked + " (" + meets + ")"; }

std::string AutoChoice::summary() const {
  return "auto: picked " + picked + " (" + errors + " for " + accuracy + ", cost " + formatValue(costMsPerSimS) +
         " ms per simulated s; most accurate, " + mostAccurate + ", costs " + formatValue(mostAccurateCost) +
         "; data: " + studies + " on " + device + ")";
}

void resolveAuto(Scene& scene, const io::Json& stated, const std::string& sceneWhere) {
  const bool modelAuto = scene.model == kAutoModel;
  const std::string model = modelAuto ? "water" : scene.model, where = sceneWhere + ": scene.accuracy";
  if (!modelAuto && scene.method != MethodMode::Auto) {
    if (!scene.accuracy.is_null())
      throw Error(sceneWhere + ": scene.accuracy is read only with \"method\": \"auto\" (add it, or remove accuracy)");
    return;
  }
  if (knownKeys(model).empty())
    throw Error(sceneWhere + ": scene.method = 'auto': no measured data for model '" + scene.model +
                (model == "fluid" ? "' alone; \"model\": \"auto\" picks balls or fluid and its step for water (" +
                                        knownKeys("water") + ")"
                                  : "' (auto works for balls, ripples and swarm)"));
  if (scene.accuracy.is_null() || (scene.accuracy.is_object() && scene.accuracy.empty()))
    throw Error(sceneWhere +
                (modelAuto
                     ? ": scene.model = 'auto' needs scene.accuracy, the error the water accepts ("
                     : ": scene.method = 'auto' needs scene.accuracy, the error the scene accepts (" + model + ": ") +
                knownKeys(model) + ")");
  if (!scene.accuracy.is_object())
    throw Error(where + ": expected an object {...}, got " + std::string(scene.accuracy.type_name()));
  std::vector<const Metric*> read;
  const std::vector<Bound> bounds = readBounds(scene.accuracy, model, where, read);
  std::vector<std::pair<std::string, io::CsvTable>> studies;
  for (const std::string& study : read[0]->studies) {
    if (!fs::exists(studyFile(study)))
      throw Error(where + "." + read[0]->key + ": accuracy data '" + studyFile(study).string() +
                  "' is missing: run `tidepool sweep " + study +
                  " --ship` (on the GPU machine) to measure and ship it");
    studies.emplace_back(study, io::CsvTable(studyFile(study)));
  }

  // Each pick starts from the scene's params as read, or ("model": "auto") the same particles as balls.
  const SceneParams asRead = scene.params;
  const SceneParams ballsStart =
      modelAuto ? SceneParams(BallsSceneParams{asBalls(asRead.as<FluidSceneParams>().model, balls::Params{}),
                                               asRead.as<FluidSceneParams>().view})
                : asRead;
  auto picked = [&](const Candidate& c) {
    SceneParams p = c.model == "balls" ? ballsStart : asRead;
    write(c.settings, p);
    return p;
  };
  std::vector<Candidate> rows = candidates({model, asRead, ballsStart, scene.accuracy, read, studies, where});
  if (modelAuto) {  // every key a pick may set: the scene may state none of them
    Settings any;
    for (const Candidate& c : rows) any.insert(any.end(), c.settings.begin(), c.settings.end());
    checkConflicts(stated, any, sceneWhere, modelAuto);
  }
  Selection s;
  try {
    s = selectCheapest(rows, bounds, where);
  } catch (const Error& e) {
    std::vector<std::string> files;
    for (const auto& [study, table] : studies) files.push_back(studyFile(study).string());
    throw Error(std::string(e.what()) + "; rows: " + join(files));
  }
  if (!modelAuto) checkConflicts(stated, s.chosen->settings, sceneWhere, modelAuto);

  AutoChoice c;
  std::set<std::string> devices;
  for (std::size_t b = 0; b < bounds.size(); ++b) {
    const Metric& m = *read[b];
    auto value = [&](double v) { return m.percent ? formatValue(100.0 * v) + "%" : formatValue(v); };
    const std::string sep = b ? ", " : "", name = m.words.empty() ? m.key : m.words;
    c.accuracy += sep + name + " <= " + value(bounds[b].value);
    c.errors += sep + name + " " + value(s.chosen->guaranteed[b]);
    c.meets += sep + name + " " + value(s.chosen->guaranteed[b]) + " <= " + value(bounds[b].value);
  }
  for (const auto& [study, table] : studies) {
    c.studies += (c.studies.empty() ? "" : ", ") + study;
    if (devices.insert(table.text(0, "device")).second)
      c.device += (c.device.empty() ? "" : ", ") + table.text(0, "device");
  }
  c.model = s.chosen->model;
  c.picked = s.chosen->label;
  c.costMsPerSimS = s.chosen->cost;
  c.mostAccurate = s.mostAccurate->label;
  c.mostAccurateCost = s.mostAccurate->cost;
  c.settings = s.chosen->settings;
  c.mostAccurateParams = picked(*s.mostAccurate);
  scene.params = picked(*s.chosen);
  if (modelAuto) {
    scene.model = s.chosen->model;
    scene.method = MethodMode::Auto;
  }
  log::info(c.summary());
  scene.autoChoice = c;
}

fs::path accuracyDir() { return io::findAssetDir() / "accuracy"; }

std::vector<std::string> shippedStudies() {
  std::vector<std::string> out;
  for (const Metric& m : metrics())
    for (const std::string& study : m.studies)
      if (std::find(out.begin(), out.end(), study) == out.end()) out.push_back(study);
  return out;
}

fs::path shipStudy(const std::string& study, const fs::path& csv) {
  const std::vector<std::string> shipped = shippedStudies();
  if (std::find(shipped.begin(), shipped.end(), study) == shipped.end())
    throw Error("--ship: method auto reads no data from " + study + " (it reads " + join(shipped) + ")");
  const io::CsvTable table(csv);
  for (const char* column : {"method", "dt", "gpu_ms_per_sim_s", "stable", "device"})
    if (!table.has(column)) throw Error("--ship: '" + csv.string() + "' has no column '" + column + "'");
  for (const Metric& m : metrics()) {
    if (std::find(m.studies.begin(), m.studies.end(), study) == m.studies.end()) continue;
    std::vector<std::string> columns = {m.column};
    if (m.model == "water") columns.insert(columns.begin(), {"model", "resolution"});
    for (const std::string& column : columns)
      if (!table.has(column))
        throw Error("--ship: '" + csv.string() + "' has no column '" + column + "' (" +
                    (m.model == "water" ? "model auto" : m.model) + " " + m.key + ")");
  }
  const std::string device = table.text(0, "device");
  if (device.find("llvmpipe") != std::string::npos || device.find("softpipe") != std::string::npos)
    log::warn("--ship: " + study + " was measured on " + device +
              ": its costs are development figures; ship the GPU machine's run");
  const fs::path dest = studyFile(study);
  std::error_code ec;
  fs::create_directories(dest.parent_path(), ec);
  if (fs::exists(dest) && fs::equivalent(dest, csv, ec)) return dest;
  if (!fs::copy_file(csv, dest, fs::copy_options::overwrite_existing, ec))
    throw Error("--ship: cannot copy '" + csv.string() + "' to '" + dest.string() + "': " + ec.message());
  return dest;
}

}  // namespace tidepool
