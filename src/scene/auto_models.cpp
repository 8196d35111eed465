#include "scene/auto_models.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>

#include "base/error.h"
#include "sim/balls/balls_params.h"
#include "sim/ripples/ripples_params.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool::automethod {

double decimal(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  double d = value;
  std::from_chars(text, end, d);
  return d;
}

namespace {

// What every row holds: cost, stability and the metric columns of the stated bounds.
Candidate basics(const ModelInput& in, const io::CsvTable& t, std::size_t row) {
  Candidate c;
  c.cost = t.number(row, "gpu_ms_per_sim_s");
  c.stable = t.number(row, "stable") != 0;
  for (const Source* s : in.metrics) c.errors.push_back(std::abs(t.number(row, s->column)));  // signed drifts
  return c;
}

}  // namespace

const std::vector<Source>& sources() {
  static const std::vector<Source> table = {
      {"swarm",
       "energyDrift",
       "energy_error",
       {"swarm-orbit", "swarm-precision"},
       "max |dE|/s over 10 orbits of the reference orbit, relative to the attractor strength"},
      {"ripples",
       "phaseError",
       "phase_error",
       {"ripples-dispersion"},
       "|c_measured/c - 1| of a plane wave at the scene's cells per wavelength"},
      {"balls",
       "maxOverlap",
       "max_overlap_r",
       {"balls-settle"},
       "largest overlap of two balls in the settled water block, fraction of r"},
      {"balls",
       "energyDrift",
       "energy_drift",
       {"balls-settle"},
       "|energy of the settled block - the rigid stack's| per ball, in units of m g r"},
      {"balls",
       "restitutionError",
       "restitution_error",
       {"balls-restitution"},
       "|e_measured/e - 1| of one spring-dashpot bounce"},
  };
  return table;
}

std::vector<std::string> extraKeys(const std::string& model) {
  if (model == "ripples") return {"wavelength", "wavelengthCells"};
  return {};
}

// Swarm rows: method "<integrator>" (fp32) or "<integrator> <precision>"; dt is absolute. The
// stage keeps each step at most max_dt by adding substeps.
std::vector<Candidate> swarmCandidates(const ModelInput& in) {
  std::vector<Candidate> out;
  for (const auto& [study, t] : in.tables.studies)
    for (std::size_t r = 0; r < t.rows(); ++r) {
      std::istringstream words(t.text(r, "method"));
      std::string integrator, storage = "fp32", extra;
      words >> integrator;
      words >> storage;
      const int integratorIndex = indexOf(sim::kIntegratorNames, integrator);
      const int storageIndex = indexOf(sim::kStorageNames, storage);
      if (words >> extra || integratorIndex < 0 || storageIndex < 0)
        throw Error(t.where(r) + ": method '" + t.text(r, "method") + "' is not '<swarm integrator> [fp32|fp16]'");
      Candidate c = basics(in, t, r);
      const double dt = t.number(r, "dt");
      c.family = integrator + " " + storage;
      c.step = dt;
      c.label = c.family + ", dt <= " + formatValue(dt) + " s";
      c.settings = {pick("integrator", &sim::SwarmParams::integrator, sim::Integrator(integratorIndex)),
                    pick("storage", &sim::SwarmParams::storage, sim::Storage(storageIndex)),
                    pick("max_dt", &sim::SwarmParams::maxDt, float(dt))};
      out.push_back(std::move(c));
    }
  return out;
}

// Ripples rows: a Courant number C and cells per wavelength N. With "wavelengthCells" the grid is
// the scene's and only C is picked (from rows at the largest measured N not above it); with
// "wavelength" (m) the pick also sets the cell size to wavelength / N, keeping the pool's size.
std::vector<Candidate> ripplesCandidates(const ModelInput& in) {
  const ripples::Params& scene = in.params.model<ripples::Params>();
  if (scene.rule != ripples::Rule::Wave)
    throw Error(in.where + ": the dispersion data measures the wave rule; this scene uses rule '" +
                ripples::kRuleNames[int(scene.rule)] + "'");
  const bool fixedGrid = in.accuracy.contains("wavelengthCells");
  if (fixedGrid == in.accuracy.contains("wavelength"))
    throw Error(in.where +
                ": state the shortest wave that must keep its speed, as wavelength (m; the pick may change "
                "the grid) or wavelengthCells (cells of the scene's grid), one of them");
  const double width = scene.width, height = scene.height, cellSize = decimal(scene.cellSize);
  const double courantCap = kStabilityMargin * ripples::kCourantLimit2D;
  const io::CsvTable& t = in.tables.studies.at(0).second;
  double cells = 0;  // fixed grid: the measured N used for the scene
  if (fixedGrid) {
    const io::Json& given = in.accuracy.at("wavelengthCells");
    if (!given.is_number() || !(given.get<double>() >= 2 && given.get<double>() <= 1e5))
      throw Error(in.where + ".wavelengthCells = " + io::excerpt(given) + " is out of range [2, 100000]");
    double coarsest = INFINITY;
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const double n = t.number(r, "cells_per_wavelength");
      coarsest = std::min(coarsest, n);
      if (n <= given.get<double>()) cells = std::max(cells, n);
    }
    if (cells == 0)
      throw Error(in.where + ".wavelengthCells " + formatValue(given.get<double>()) +
                  " is below the coarsest measured (" + formatValue(coarsest) + " cells per wavelength)");
  } else {
    const io::Json& given = in.accuracy.at("wavelength");
    if (!given.is_number() || !(given.get<double>() > 0 && given.get<double>() <= 1e4))
      throw Error(in.where + ".wavelength = " + io::excerpt(given) + " is out of range (0, 10000] m");
  }
  std::vector<Candidate> out;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double n = t.number(r, "cells_per_wavelength"), courant = t.number(r, "courant");
    if (courant > courantCap || (fixedGrid && n != cells)) continue;
    Candidate c = basics(in, t, r);
    c.family = formatValue(n) + " cells per wavelength";
    c.step = courant;
    c.settings = {pick("auto_substeps", &ripples::Params::autoSubsteps, true),
                  pick("courant_target", &ripples::Params::courantTarget, float(courant / ripples::kCourantLimit2D))};
    c.label = "C <= " + formatValue(courant) + " at " + c.family;
    if (!fixedGrid) {
      const double dx = in.accuracy.at("wavelength").get<double>() / n;
      const int w = int(std::lround(width * cellSize / dx)), h = int(std::lround(height * cellSize / dx));
      if (w < 16 || h < 16 || w > 4096 || h > 4096 || dx < 1e-4 || dx > 10) continue;  // the grid's ranges
      c.settings.push_back(rescale("cell_size", &ripples::Params::cellSize, float(dx)));
      c.settings.push_back(rescale("width", &ripples::Params::width, w));
      c.settings.push_back(rescale("height", &ripples::Params::height, h));
      c.label += " (" + std::to_string(w) + "x" + std::to_string(h) + " cells of " + formatValue(dx) + " m)";
    }
    out.push_back(std::move(c));
  }
  return out;
}

BallsMethod parseBallsMethod(const io::CsvTable& t, std::size_t row, bool integratorOnly) {
  const std::string method = t.text(row, "method");
  std::string contact = "spring-dashpot", integrator = method;
  double stepsPerContact = 0;
  if (!integratorOnly) {
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
    throw Error(t.where(row) + ": method '" + method + "' is not '<balls contact>[ tc = K dt][, <integrator>]'");
  BallsMethod m;
  m.contact = balls::Contact(contactIndex);
  if (!integrator.empty()) m.integrator = balls::Integrator(integratorIndex);
  m.stepsPerContact = stepsPerContact;
  m.words = contact + (integrator.empty() ? "" : ", " + integrator);
  return m;
}

Settings ballsSettings(const BallsMethod& m, double dt, double contactTime, double frame) {
  const bool springDashpot = m.contact == balls::Contact::SpringDashpot;
  if (!(dt > 0) || frame / dt - 1e-6 > 1000) return {};  // substeps: the param's range
  // Symplectic Euler and Verlet keep an undamped spring while omega0 dt < 2: dt < 0.64 t_c.
  if (springDashpot && m.integrator != balls::Integrator::ExplicitEuler &&
      dt > kStabilityMargin * 2.0 / std::numbers::pi * contactTime)
    return {};
  const int substeps = std::max(1, int(std::ceil(frame / dt - 1e-6)));
  Settings out = {pick("engine.contact", &balls::Params::contact, m.contact),
                  rescale("engine.dt", &balls::Params::dt, float(frame / substeps)),
                  rescale("engine.substeps", &balls::Params::substeps, substeps)};
  if (m.integrator) out.push_back(pick("engine.integrator", &balls::Params::integrator, *m.integrator));
  if (m.stepsPerContact > 0 && springDashpot)
    out.push_back(pick("engine.contact_time", &balls::Params::contactTime, float(contactTime)));
  return out;
}

// Balls rows: balls-restitution (method = integrator, spring-dashpot, steps_per_contact; dt follows
// the scene's contact time) or balls-settle (method = "<contact>[ tc = K dt], <integrator>", dt:
// the overlap there is set by the contact's stiffness, so a spring-dashpot pick also sets the
// contact time to K dt). The frame keeps its simulated time (the scene's dt x substeps): substeps
// grow until a step is at most the picked dt.
std::vector<Candidate> ballsCandidates(const ModelInput& in) {
  const balls::Params& scene = in.params.model<balls::Params>();
  const double sceneContactTime = decimal(scene.contactTime);
  const double frame = decimal(scene.dt) * scene.substeps;
  std::vector<Candidate> out;
  for (const auto& [study, t] : in.tables.studies)
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const BallsMethod m = parseBallsMethod(t, r, study == "balls-restitution");
      const bool springDashpot = m.contact == balls::Contact::SpringDashpot;
      Candidate c = basics(in, t, r);
      double dt = t.number(r, "dt"), contactTime = sceneContactTime;
      std::string stepWords = "dt <= " + formatValue(dt) + " s";
      c.step = dt;
      if (springDashpot && m.stepsPerContact > 0) {
        contactTime = m.stepsPerContact * dt;
        stepWords += ", t_c = " + formatValue(contactTime) + " s";
      } else if (springDashpot && t.has("steps_per_contact")) {
        const double steps = t.number(r, "steps_per_contact");
        dt = sceneContactTime / steps;
        stepWords = "dt <= " + formatValue(dt) + " s (t_c/dt = " + formatValue(steps) + ")";
        c.step = 1.0 / steps;
      }
      c.settings = ballsSettings(m, dt, contactTime, frame);
      if (c.settings.empty()) continue;
      c.family = t.text(r, "method");
      c.label = m.words + ", " + stepWords;
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace tidepool::automethod
