// `tidepool validate <scene> --probe energy,overlap,density,front,height,probes --every K --until T --csv out.csv`:
// runs a balls or fluid scene headless and writes probe time series (the dam-break measurements:
// surge front in units of the column width a, residual column height in units of its height; the
// density error, mean and max of ρ/ρ0 − 1 over compressed particles, for both models with the
// fluid's kernel: sim/fluid/density_probe.h; the scene's own probes, params.probes:
// sim/water/probes.h). Energies: balls per unit mass (m²/s²), fluid in J.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "base/log.h"
#include "base/progress.h"
#include "cli/commands.h"
#include "gl/context.h"
#include "io/echo.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "sim/water/probes.h"
#include "sim/water/water_init.h"

namespace tidepool::cli {
namespace {

const std::vector<std::string> kProbes = {"energy", "overlap", "density", "front", "height", "probes"};

std::vector<std::string> parseProbes(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ',');) {
    if (std::find(kProbes.begin(), kProbes.end(), p) == kProbes.end())
      throw Error("--probe '" + io::printable(p) + "' is not one of: energy, overlap, density, front, height, probes");
    out.push_back(p);
  }
  return out;
}

// One sample of either model, in the columns validate writes.
struct Sample {
  double time = 0;
  std::size_t count = 0, nonFinite = 0;
  double kinetic = 0, potential = 0, maxOverlap = NAN, meanOverlap = NAN, densityMean = 0, densityMax = 0,
         densitySigned = 0;
  double front = 0, backHeight = 0;
};

// The model a scene names, stepped and sampled alike.
class Run {
 public:
  Run(const Scene& scene, gl::ShaderLibrary& shaders) : m_probe(shaders), m_probes(shaders) {
    if (scene.model == "balls") {
      m_balls = std::make_unique<balls::Balls>(shaders, ballsParams(scene));
      m_water = balls::resolved(m_balls->params());
    } else if (scene.model == "fluid") {
      m_fluid = std::make_unique<fluid::Fluid>(shaders, fluidScene(scene).model);
      m_water = m_fluid->water();
    } else {
      throw Error("validate runs balls and fluid scenes; '" + io::printable(scene.name) + "' is a " + scene.model +
                  " scene");
    }
  }
  const water::Setup& water() const { return m_water; }
  std::vector<double> probes() {
    return m_probes.measure(m_balls ? static_cast<water::ParticleWater&>(*m_balls) : *m_fluid);
  }
  float radius() const { return m_balls ? m_balls->radius() : m_fluid->radius(); }
  double time() const { return m_balls ? m_balls->time() : m_fluid->time(); }
  void step() {
    if (m_balls)
      m_balls->stepOnce();
    else
      m_fluid->stepOnce();
  }
  Sample sample(bool density) {
    Sample out;
    if (m_balls) {
      const balls::Stats s = m_balls->stats();
      out = {s.time,        s.count, s.nonFinite, s.kinetic, s.potential, s.maxOverlap,
             s.meanOverlap, 0,       0,           0,         s.front,     s.backHeight};
      if (density) {  // the balls' configuration read with the fluid's kernel, h = 2 × spacing 2r
        const fluid::Stats d = m_probe.measure(*m_balls, {2.0f * m_balls->radius()}, m_balls->gravity(), s.time);
        out.densityMean = d.compressionMean;
        out.densityMax = d.compressionMax;
        out.densitySigned = d.densityMean;
      }
    } else {
      const fluid::Stats s = m_fluid->stats();
      out = {s.time, s.count,           s.nonFinite,      s.kinetic,     s.potential, NAN,
             NAN,    s.compressionMean, s.compressionMax, s.densityMean, s.front,     s.backHeight};
    }
    return out;
  }

 private:
  std::unique_ptr<balls::Balls> m_balls;
  std::unique_ptr<fluid::Fluid> m_fluid;
  water::Setup m_water;
  fluid::DensityProbe m_probe;
  water::Probes m_probes;
};

int validate(const std::string& sceneName, const std::string& probeText, int every, double until,
             const std::string& csvPath, const std::string& backend) {
  const std::vector<std::string> probes = parseProbes(probeText);
  const Scene scene = loadScene(resolveScenePath(sceneName));
  if (scene.model != "balls" && scene.model != "fluid")
    throw Error("validate runs balls and fluid scenes; '" + io::printable(scene.name) + "' is a " + scene.model +
                " scene");
  auto context = gl::createHeadlessContext({gl::parseBackend(backend), false});
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  Run model(scene, shaders);
  const water::Setup& params = model.water();
  // Scales of the dam-break probes: the initial column's width a and height h0.
  const bool column = params.fill == water::Fill::Block;
  const glm::vec3 lo = column ? glm::max(params.fillMin, params.domainMin) : params.domainMin;
  const glm::vec3 hi = column ? glm::min(params.fillMax, params.domainMax) : params.domainMax;
  const double a = hi.x - lo.x, h0 = hi.z - lo.z;

  auto has = [&](const char* p) { return std::find(probes.begin(), probes.end(), p) != probes.end(); };
  if (has("probes") && params.probes.empty())
    throw Error("--probe probes: the scene '" + scene.name + "' lists no probes (params.probes)");
  if (has("probes")) model.probes();  // what it cannot measure: before any output

  std::ofstream file;
  if (!csvPath.empty()) {
    file.open(csvPath);
    if (!file) throw Error("cannot write '" + io::shownPath(csvPath) + "'");
  }
  std::ostream& out = csvPath.empty() ? std::cout : file;
  out << "time_s,count,nan";
  if (has("energy")) out << ",kinetic,potential,total";
  if (has("overlap")) out << ",max_overlap_r,mean_overlap_r";
  if (has("density")) out << ",density_error_mean,density_error_max,density_mean_signed";
  if (has("front")) out << ",front_over_a";
  if (has("height")) out << ",height_over_h0";
  if (has("probes"))
    for (const std::string& c : water::probeColumns(params.probes)) out << "," << c;
  out << "\n";
  int samples = 0;
  char horizon[64];
  std::snprintf(horizon, sizeof horizon, "until t = %g s, a sample every %d steps", until, every);
  log::info(scene.name + ": " + groupedCount(model.sample(false).count) + " particles, " + horizon);
  // Simulated milliseconds as the unit of work: the number of steps to `until` is the model's to choose.
  Progress progress("validate " + scene.name, std::max(1, int(std::lround(until * 1e3))), true, "ms simulated");
  for (long step = 0;; ++step) {
    progress.update(int(std::lround(std::min(model.time(), until) * 1e3)));
    if (step % every == 0) {
      const Sample s = model.sample(has("density"));
      out << s.time << "," << s.count << "," << s.nonFinite;
      if (has("energy")) out << "," << s.kinetic << "," << s.potential << "," << s.kinetic + s.potential;
      if (has("overlap")) out << "," << s.maxOverlap << "," << s.meanOverlap;
      if (has("density")) out << "," << s.densityMean << "," << s.densityMax << "," << s.densitySigned;
      if (has("front")) out << "," << (s.front - params.domainMin.x + model.radius()) / a;  // particle surface
      if (has("height")) out << "," << (s.backHeight - params.domainMin.z + model.radius()) / h0;
      if (has("probes"))
        for (double v : model.probes()) out << "," << v;
      out << "\n";
      ++samples;
      if (s.nonFinite > 0)
        throw Error(scene.model + " diverged by t = " + std::to_string(s.time) + " s: " + std::to_string(s.nonFinite) +
                    " particles are NaN (see the CSV)");
    }
    if (model.time() >= until - 1e-12) break;
    model.step();
  }
  progress.finish();
  if (!csvPath.empty()) std::fprintf(stderr, "wrote %d samples to %s\n", samples, csvPath.c_str());
  return 0;
}

}  // namespace

Command addValidate(CLI::App& app) {
  auto* sub = app.add_subcommand("validate", "run a balls or fluid scene headless and write probe time series (CSV)");
  struct Opts {
    std::string scene, probes = "energy,overlap,front,height", csv, backend = "auto";
    int every = 100;
    double until = 1.0;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "balls or fluid scene file or name")->required();
  sub->add_option("--probe", o->probes, "comma list of energy, overlap, density, front, height, probes");
  sub->add_option("--every", o->every, "steps between samples")->check(CLI::Range(1, 100000000));
  sub->add_option("--until", o->until, "simulated seconds")->check(finiteRange(0.0, 1e9));
  sub->add_option("--csv", o->csv, "output file (default: standard output)");
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  return {sub, [o] { return validate(o->scene, o->probes, o->every, o->until, o->csv, o->backend); }};
}

}  // namespace tidepool::cli
