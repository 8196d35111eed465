// What "method": "auto" and "model": "auto" (scene/auto/auto.h) choose among: the metrics a scene
// may bound, each model's study rows read as candidate settings, and the choice, the cheapest row
// whose error meets every stated bound, with a safety margin.
//
//   candidates: {rk4 fp32 dt 0.063: cost 0.30, error 3.7e-5}, {verlet fp32 dt 0.016: cost 0.95, error 5.0e-4} ...
//   selectCheapest(candidates, {{"energyDrift", 1e-3}}, "scene.accuracy")  ->  rk4 fp32 dt 0.063
//
// Two margins, both documented in docs/AUTO.md:
//  - the engine may take smaller steps than the pick (whole substeps per frame), and smaller is not
//    always better (RK4 in fp32 gains round-off; the 2D leapfrog's phase error grows as C falls),
//    so a row counts with the worst error measured in its family at its step or any smaller one;
//  - the scene is not the study's reference problem, so that worst error must stay under the
//    bound divided by kMetricMargin.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/csv.h"
#include "io/json.h"
#include "scene/scene_params.h"

namespace tidepool::automethod {

inline constexpr double kMetricMargin = 2.0;     // measured error x 2 must meet the bound
inline constexpr double kStabilityMargin = 0.9;  // picks stay under 90% of a known stability limit

// An accuracy key a scene may bound and the study column that measures it.
struct Metric {
  std::string model;                 // "swarm", "ripples", "balls"; "water" for "model": "auto"
  std::string key;                   // in the scene's "accuracy" object
  std::string column;                // the study CSV's metric column
  std::vector<std::string> studies;  // assets/accuracy/<study>.csv, all read
  std::string words = "";            // how the log and the window name it: "density error" ("": the key)
  bool percent = false;              // shown as a percentage (a fraction in the data)
};
const std::vector<Metric>& metrics();
std::string knownKeys(const std::string& model);  // "densityError, frontError"

// One parameter a pick sets: a field of the model's typed params, named by its key in scene files.
struct Setting {
  std::string key;                          // as the scene file names it: "engine.dt"
  bool rescaled = false;                    // rescaled rather than chosen (the frame's time, the pool's size):
                                            // the scene may state it too
  std::function<void(SceneParams&)> write;  // sets the field to the picked value
};
using Settings = std::vector<Setting>;
void write(const Settings& settings, SceneParams& params);

// pick("engine.contact", &balls::Params::contact, balls::Contact::SpringDashpot); a field of the water setup
// (dt, substeps) names the model: pick<balls::Params, float>("engine.dt", &balls::Params::dt, dt).
template <class Model, class T>
Setting pick(const char* key, T Model::*field, std::type_identity_t<T> value, bool rescaled = false) {
  return {key, rescaled, [field, value](SceneParams& p) { p.model<Model>().*field = value; }};
}

struct Bound {
  std::string key;  // accuracy key, e.g. "energyDrift"
  double value;     // the largest error the scene accepts
};

struct Candidate {
  std::string label;           // the settings in words: "rk4 fp32, dt <= 0.0628 s"
  std::string model;           // "model": "auto": the model the row runs, "balls" or "fluid"; else ""
  std::string family;          // rows of one family differ only in `step`
  double step = 0;             // what the engine may make smaller than picked (dt, Courant number)
  double cost = 0;             // GPU ms per simulated second (the study's column)
  std::vector<double> errors;  // measured, one per bound
  bool stable = true;
  Settings settings;               // what the pick writes into the scene's params
  std::vector<double> guaranteed;  // worst error of the family at this step or below (filled by selectCheapest)
};

// A scene's rows, as each model's reader sees them.
struct Rows {
  std::string model;                  // a Metric's: the "water" rows hold balls and fluid
  const SceneParams& params;          // the scene's typed params, as read (water: the fluid's)
  const SceneParams& asBalls;         // water: the same particles as balls; else `params`
  const io::Json& accuracy;           // the scene's accuracy object (extra keys such as wavelength)
  std::vector<const Metric*> bounds;  // one per bound, in order
  const std::vector<std::pair<std::string, io::CsvTable>>& studies;  // name, rows
  std::string where;                                                 // "file: scene.accuracy"
};
// Candidates from every row that applies (rows past a stability margin, needing more than 1000
// substeps or the scene cannot run are left out). Throws Error naming the file and line of a row
// it cannot read, or the measured spacings when no water row is at the scene's.
std::vector<Candidate> candidates(const Rows& rows);

struct Selection {
  const Candidate* chosen = nullptr;
  const Candidate* mostAccurate = nullptr;  // the smallest measured error (first bound) among stable rows
};
// Fills `guaranteed` and returns the cheapest stable candidate with guaranteed x kMetricMargin <=
// bound for every bound. Throws Error when none does: "<where>.<key> <bound> cannot be met by any
// measured setting; best is <label> with <error> (needs <= <bound / margin> ...)".
Selection selectCheapest(std::vector<Candidate>& candidates, const std::vector<Bound>& bounds,
                         const std::string& where);

std::string formatValue(double v);  // 3 significant digits: 0.000498 -> "0.000498", 1e-06 -> "1e-06"

}  // namespace tidepool::automethod
