// One reader per model: how a study row becomes a candidate's settings for the scene.
#include "scene/auto/candidates.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <sstream>

#include "base/error.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/fluid_params.h"
#include "sim/ripples/ripples_params.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool::automethod {
namespace {

// The number a scene wrote for a float parameter: the shortest decimal that reads back as that
// float (0.0002f -> 0.0002), so that the frame's simulated time dt x substeps is the scene's
// 0.0002 x 25 = 0.005 s, which the picked substeps then divide.
double decimal(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  double d = value;
  std::from_chars(text, end, d);
  return d;
}

// The fewest substeps of at most `dt` s that make up the frame; 0 when dt is not positive or
// more than 1000 substeps (the param's range) would be needed.
int substepsFor(double frame, double dt) {
  if (!(dt > 0) || frame / dt - 1e-6 > 1000) return 0;
  return std::max(1, int(std::ceil(frame / dt - 1e-6)));
}

std::string ms(double seconds) { return formatValue(seconds * 1e3) + " ms"; }

template <std::size_t N>
int indexOf(const std::array<const char*, N>& names, const std::string& name) {
  const auto it = std::find_if(names.begin(), names.end(), [&](const char* n) { return name == n; });
  return it == names.end() ? -1 : int(it - names.begin());
}

// What every row holds: cost, stability and the metric columns of the stated bounds.
Candidate basics(const Rows& in, const io::CsvTable& t, std::size_t row) {
  Candidate c;
  c.cost = t.number(row, "gpu_ms_per_sim_s");
  c.stable = t.number(row, "stable") != 0;
  for (const Metric* m : in.bounds) c.errors.push_back(std::abs(t.number(row, m->column)));  // signed drifts
  return c;
}

// Swarm rows: method "<integrator>" (fp32) or "<integrator> <precision>"; dt is absolute. The
// stage keeps each step at most max_dt by adding substeps.
bool swarmRow(const io::CsvTable& t, std::size_t r, Candidate& c) {
  std::istringstream words(t.text(r, "method"));
  std::string integrator, storage = "fp32", extra;
  words >> integrator;
  words >> storage;
  const int integratorIndex = indexOf(sim::kIntegratorNames, integrator);
  const int storageIndex = indexOf(sim::kStorageNames, storage);
  if (words >> extra || integratorIndex < 0 || storageIndex < 0)
    throw Error(t.where(r) + ": method '" + t.text(r, "method") + "' is not '<swarm integrator> [fp32|fp16]'");
  const double dt = t.number(r, "dt");
  c.family = integrator + " " + storage;
  c.step = dt;
  c.label = c.family + ", dt <= " + formatValue(dt) + " s";
  c.settings = {pick("integrator", &sim::SwarmParams::integrator, sim::Integrator(integratorIndex)),
                pick("storage", &sim::SwarmParams::storage, sim::Storage(storageIndex)),
                pick("max_dt", &sim::SwarmParams::maxDt, float(dt))};
  return true;
}

// Ripples rows: a Courant number C and cells per wavelength N. With "wavelengthCells" the grid is
// the scene's and only C is picked (from rows at the largest measured N not above it); with
// "wavelength" (m) the pick also sets the cell size to wavelength / N, keeping the pool's size.
struct RipplesTarget {
  std::optional<double> cells;  // the measured N used for the scene's own grid
  double wavelength = 0;        // else: the shortest wave, m
};

RipplesTarget ripplesTarget(const Rows& in, const io::CsvTable& t) {
  const ripples::Params& scene = in.params.model<ripples::Params>();
  if (scene.rule != ripples::Rule::Wave)
    throw Error(in.where + ": the dispersion data measures the wave rule; this scene uses rule '" +
                ripples::kRuleNames[int(scene.rule)] + "'");
  const bool fixedGrid = in.accuracy.contains("wavelengthCells");
  if (fixedGrid == in.accuracy.contains("wavelength"))
    throw Error(in.where +
                ": state the shortest wave that must keep its speed, as wavelength (m; the pick may change "
                "the grid) or wavelengthCells (cells of the scene's grid), one of them");
  if (!fixedGrid) {
    const io::Json& given = in.accuracy.at("wavelength");
    if (!given.is_number() || !(given.get<double>() > 0 && given.get<double>() <= 1e4))
      throw Error(in.where + ".wavelength = " + io::excerpt(given) + " is out of range (0, 10000] m");
    return {std::nullopt, given.get<double>()};
  }
  const io::Json& given = in.accuracy.at("wavelengthCells");
  if (!given.is_number() || !(given.get<double>() >= 2 && given.get<double>() <= 1e5))
    throw Error(in.where + ".wavelengthCells = " + io::excerpt(given) + " is out of range [2, 100000]");
  double cells = 0, coarsest = INFINITY;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double n = t.number(r, "cells_per_wavelength");
    coarsest = std::min(coarsest, n);
    if (n <= given.get<double>()) cells = std::max(cells, n);
  }
  if (cells == 0)
    throw Error(in.where + ".wavelengthCells " + formatValue(given.get<double>()) +
                " is below the coarsest measured (" + formatValue(coarsest) + " cells per wavelength)");
  return {cells, 0};
}

bool ripplesRow(const Rows& in, const RipplesTarget& target, const io::CsvTable& t, std::size_t r, Candidate& c) {
  const ripples::Params& scene = in.params.model<ripples::Params>();
  const double n = t.number(r, "cells_per_wavelength"), courant = t.number(r, "courant");
  if (courant > kStabilityMargin * ripples::kCourantLimit2D || (target.cells && n != *target.cells)) return false;
  c.family = formatValue(n) + " cells per wavelength";
  c.step = courant;
  c.settings = {pick("auto_substeps", &ripples::Params::autoSubsteps, true),
                pick("courant_target", &ripples::Params::courantTarget, float(courant / ripples::kCourantLimit2D))};
  c.label = "C <= " + formatValue(courant) + " at " + c.family;
  if (target.cells) return true;
  const double dx = target.wavelength / n, cellSize = decimal(scene.cellSize);
  const int w = int(std::lround(scene.width * cellSize / dx)), h = int(std::lround(scene.height * cellSize / dx));
  if (w < 16 || h < 16 || w > 4096 || h > 4096 || dx < 1e-4 || dx > 10) return false;  // the grid's ranges
  c.settings.push_back(pick("cell_size", &ripples::Params::cellSize, float(dx), true));
  c.settings.push_back(pick("width", &ripples::Params::width, w, true));
  c.settings.push_back(pick("height", &ripples::Params::height, h, true));
  c.label += " (" + std::to_string(w) + "x" + std::to_string(h) + " cells of " + formatValue(dx) + " m)";
  return true;
}

// Balls rows: balls-restitution (method = integrator of a spring-dashpot bounce, steps_per_contact;
// dt follows the scene's contact time) or balls-settle and the water studies (method =
// "<contact>[ tc = K dt][, <integrator>]", dt: the overlap there is set by the contact's
// stiffness, so a spring-dashpot pick also sets the contact time to K dt). The frame keeps its
// simulated time: substeps grow until a step is at most the picked dt.
bool ballsRow(const Rows& in, double frame, const io::CsvTable& t, std::size_t r, Candidate& c) {
  const std::string method = t.text(r, "method");
  const bool perContact = t.has("steps_per_contact");
  std::string contact = "spring-dashpot", integrator = method;
  double stepsPerContact = 0;
  if (!perContact) {
    const std::size_t comma = method.find(", ");
    std::istringstream words(method.substr(0, comma));
    std::string tc, eq, dtWord;
    words >> contact;
    if (words >> tc >> eq >> stepsPerContact >> dtWord && !(tc == "tc" && eq == "=" && dtWord == "dt"))
      stepsPerContact = -1;
    integrator = comma == std::string::npos ? "" : method.substr(comma + 2);
  }
  const int contactIndex = indexOf(balls::kContactNames, contact);
  const int integratorIndex = integrator.empty() ? 0 : indexOf(balls::kIntegratorNames, integrator);
  if (contactIndex < 0 || integratorIndex < 0 || stepsPerContact < 0)
    throw Error(t.where(r) + ": method '" + method + "' is not '<balls contact>[ tc = K dt][, <integrator>]'");
  const bool springDashpot = balls::Contact(contactIndex) == balls::Contact::SpringDashpot;
  const bool explicitEuler =
      !integrator.empty() && balls::Integrator(integratorIndex) == balls::Integrator::ExplicitEuler;
  const std::string words = contact + (integrator.empty() ? "" : ", " + integrator);

  double dt = t.number(r, "dt"), contactTime = decimal(in.asBalls.model<balls::Params>().contactTime);
  std::string stepWords = "dt <= " + formatValue(dt) + " s", contactWords;
  c.step = dt;
  if (springDashpot && stepsPerContact > 0) {
    contactTime = stepsPerContact * dt;
    contactWords = ", t_c = " + (in.model == "water" ? ms(contactTime) : formatValue(contactTime) + " s");
  } else if (springDashpot && perContact) {
    const double steps = t.number(r, "steps_per_contact");
    dt = contactTime / steps;
    stepWords = "dt <= " + formatValue(dt) + " s (t_c/dt = " + formatValue(steps) + ")";
    c.step = 1.0 / steps;
  }
  const int substeps = substepsFor(frame, dt);
  // Symplectic Euler and Verlet keep an undamped spring while omega0 dt < 2: dt < 0.64 t_c.
  if (!substeps || (springDashpot && !explicitEuler && dt > kStabilityMargin * 2.0 / std::numbers::pi * contactTime))
    return false;
  c.settings = {pick("engine.contact", &balls::Params::contact, balls::Contact(contactIndex)),
                pick<balls::Params, float>("engine.dt", &balls::Params::dt, float(frame / substeps), true),
                pick<balls::Params, int>("engine.substeps", &balls::Params::substeps, substeps, true)};
  if (!integrator.empty())
    c.settings.push_back(pick("engine.integrator", &balls::Params::integrator, balls::Integrator(integratorIndex)));
  if (stepsPerContact > 0 && springDashpot)
    c.settings.push_back(pick("engine.contact_time", &balls::Params::contactTime, float(contactTime)));
  c.label = in.model == "water" ? "balls, " + words + ", dt " + ms(frame / substeps) + contactWords
                                : words + ", " + stepWords + contactWords;
  return true;
}

// Fluid rows (water studies), method "pbf, <k> iterations": the solver's iterations, and the step
// rescaled so that the frame keeps its simulated time.
bool fluidRow(double frame, const io::CsvTable& t, std::size_t r, Candidate& c) {
  const std::string method = t.text(r, "method");
  std::istringstream words(method);
  std::string pbf, iterationsWord, extra;
  int iterations = 0;
  if (!(words >> pbf >> iterations >> iterationsWord) || words >> extra || pbf != "pbf," ||
      (iterationsWord != "iterations" && iterationsWord != "iteration") || iterations < 1 || iterations > 100)
    throw Error(t.where(r) + ": method '" + method + "' is not 'pbf, <1 to 100> iterations'");
  if (t.has("iterations") && t.number(r, "iterations") != iterations)
    throw Error(t.where(r) + ": method '" + method + "' but iterations " + t.text(r, "iterations"));
  const double dt = t.number(r, "dt");
  const int substeps = substepsFor(frame, dt);
  if (!substeps) return false;
  const float runDt = float(frame / substeps);
  c.step = dt;
  c.label = "fluid, " + std::to_string(iterations) + (iterations == 1 ? " iteration" : " iterations") + ", dt " +
            ms(frame / substeps);
  c.settings = {
      pick("solver.iterations", &fluid::Params::iterations, iterations),
      {"engine.dt", true, [runDt](SceneParams& p) { p.model<fluid::Params>().dt = runDt; }},
      {"engine.substeps", true, [substeps](SceneParams& p) { p.model<fluid::Params>().substeps = substeps; }}};
  return true;
}

// The spacing a row was measured at, from its resolution ("spacing 0.02 m", "N = 3900, spacing
// 0.02 m"); NaN when it names none (the row then applies at any spacing).
double rowSpacing(const io::CsvTable& t, std::size_t row) {
  const std::string& text = t.text(row, "resolution");
  const std::size_t at = text.find("spacing ");
  if (at == std::string::npos) return NAN;
  const char* start = text.c_str() + at + 8;
  char* end = nullptr;
  const double d = std::strtod(start, &end);
  if (end == start || !(d > 0) || std::string(end).rfind(" m", 0) != 0)
    throw Error(t.where(row) + ": resolution '" + text + "' does not read as 'spacing <metres> m'");
  return d;
}

bool sameSpacing(double a, double b) { return std::abs(a / b - 1.0) < 1e-3; }

// Water rows (column `model`, balls or fluid): those measured at the scene's spacing, or at none.
std::vector<Candidate> waterCandidates(const Rows& in) {
  const io::CsvTable& t = in.studies.at(0).second;
  const fluid::Params& scene = in.params.model<fluid::Params>();
  const double spacing = decimal(scene.spacing()), frame = decimal(scene.dt) * scene.substeps;
  std::vector<double> measured;  // the spacings rows name
  std::vector<Candidate> out;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double rowAt = rowSpacing(t, r);
    if (std::isfinite(rowAt) &&
        std::none_of(measured.begin(), measured.end(), [&](double d) { return sameSpacing(d, rowAt); }))
      measured.push_back(rowAt);
    if (std::isfinite(rowAt) && !sameSpacing(rowAt, spacing)) continue;
    Candidate c = basics(in, t, r);
    c.model = t.text(r, "model");
    c.family = c.model + ": " + t.text(r, "method") + " at " + t.text(r, "resolution");
    if (c.model != "fluid" && c.model != "balls")
      throw Error(t.where(r) + ": model '" + c.model + "' is not balls or fluid");
    if (c.model == "fluid" ? fluidRow(frame, t, r, c) : ballsRow(in, frame, t, r, c)) out.push_back(std::move(c));
  }
  if (out.empty() && !measured.empty()) {
    std::sort(measured.begin(), measured.end());
    std::string list;
    for (double d : measured) list += (list.empty() ? "" : ", ") + formatValue(d);
    throw Error(in.where + ": no row of " + in.studies.at(0).first + " was measured at this scene's spacing " +
                formatValue(spacing) + " m (measured: " + list + " m)");
  }
  return out;
}

}  // namespace

std::vector<Candidate> candidates(const Rows& in) {
  if (in.model == "water") return waterCandidates(in);
  std::optional<RipplesTarget> ripples;
  if (in.model == "ripples") ripples = ripplesTarget(in, in.studies.at(0).second);
  const balls::Params* ballsScene = in.model == "balls" ? &in.params.model<balls::Params>() : nullptr;
  const double frame = ballsScene ? decimal(ballsScene->dt) * ballsScene->substeps : 0;
  std::vector<Candidate> out;
  for (const auto& [study, t] : in.studies)
    for (std::size_t r = 0; r < t.rows(); ++r) {
      Candidate c = basics(in, t, r);
      const bool applies = in.model == "swarm"   ? swarmRow(t, r, c)
                           : in.model == "balls" ? ballsRow(in, frame, t, r, c)
                                                 : ripplesRow(in, *ripples, t, r, c);
      if (!applies) continue;
      if (in.model == "balls") c.family = t.text(r, "method");
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace tidepool::automethod
