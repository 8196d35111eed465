// "method": "auto": a scene states the accuracy it needs and the engine picks the cheapest
// measured (method, dt, substeps, precision) that meets it, from the study data shipped in
// assets/accuracy/<study>.csv (`tidepool sweep <study> --ship` regenerates it). "model": "auto"
// does the same for water and picks the model too, balls or fluid, from rows of both.
//
//   { "model": "swarm", "method": "auto", "accuracy": { "energyDrift": 1e-3 }, "params": {...} }
//   { "model": "auto", "accuracy": { "densityError": 0.01 }, "params": { <a fluid scene's params> } }
//
// metrics() (auto/candidates.h) lists each model's accuracy keys with the study and column that
// measure them (ripples also states wavelength or wavelengthCells). The pick is written into the
// scene's typed params (integrator, storage, dt, substeps, Courant target, grid), logged at load
// and shown in the window's parameter panel. "model": "auto" then runs the picked model:
// scene.model becomes "balls" or "fluid" and scene.params that model's params (the balls from
// the fluid's with asBalls: the same water volume, so radius = spacing · 2^(1/6) / 2).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "io/json.h"
#include "scene/auto/candidates.h"
#include "scene/scene_params.h"

namespace tidepool {

struct Scene;

// "model": "auto" in a scene: water, balls or fluid as scene.accuracy needs.
inline constexpr const char* kAutoModel = "auto";

// "method" in a scene: "params" runs the params as written; "auto" picks from scene.accuracy.
enum class MethodMode { Params, Auto };
inline constexpr std::array<const char*, 2> kMethodModeNames = {"params", "auto"};

// What "method": "auto" (or "model": "auto") picked, for the log and the UI.
struct AutoChoice {
  std::string model;               // "model": "auto": the model picked, "balls" or "fluid"; else ""
  std::string accuracy;            // the bounds as stated: "energyDrift <= 0.001", "density error <= 1%"
  std::string picked;              // the settings in words: "rk4 fp32, dt <= 0.0628 s", "fluid, 4 iterations, dt 1 ms"
  std::string errors;              // its measured (worst-case) errors: "energyDrift 3.74e-05", "density error 0.35%"
  std::string meets;               // each error against its bound: "density error 0.35% <= 1%"
  double costMsPerSimS = 0;        // its cost in the study's column
  std::string mostAccurate;        // the most accurate measured setting, in words
  double mostAccurateCost = 0;     // and its cost
  std::string studies, device;     // where the numbers come from
  automethod::Settings settings;   // the fields it wrote into the scene's params
  SceneParams mostAccurateParams;  // the scene's params as the most accurate would have set them (tests compare)
  std::string summary() const;     // one line: "auto: picked ... (...; most accurate ... costs ...)"
  std::string headline() const;    // short: "auto: fluid, 4 iterations, dt 1 ms (density error 0.35% <= 1%)"
};

// Resolves "method": "auto" and "model": "auto" in place: validates scene.accuracy, picks from the
// shipped data, writes the pick into the typed scene.params and sets scene.autoChoice ("model":
// "auto", whose params were read as a fluid scene's, also sets scene.model and scene.method). A
// scene with neither must not state accuracy. Throws Error (one line naming the key) for unknown
// keys, keys of another model, out-of-range values, missing data, bounds no measured setting
// meets, and params the pick would override that `stated` (the file's "params" object) states.
// `where` prefixes messages (the scene file).
void resolveAuto(Scene& scene, const io::Json& stated, const std::string& where);

// Studies whose CSVs method or model auto reads: the ones `tidepool sweep <study> --ship` copies
// into assets/accuracy/.
std::vector<std::string> shippedStudies();
std::filesystem::path accuracyDir();  // assets/accuracy

// Checks that `csv` (a sweep's bench/results/<study>.csv) holds the columns auto reads and copies
// it to assets/accuracy/<study>.csv; returns the destination. Throws Error.
std::filesystem::path shipStudy(const std::string& study, const std::filesystem::path& csv);

}  // namespace tidepool
