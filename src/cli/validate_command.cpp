// `tidepool validate <scene> --probe energy,overlap,front,height --every K --until T --csv out.csv`:
// runs a balls scene headless and writes probe time series (the dam-break measurements:
// surge front in units of the column width a, residual column height in units of its height).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "gl/context.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"

namespace tidepool::cli {
namespace {

const std::vector<std::string> kProbes = {"energy", "overlap", "front", "height"};

std::vector<std::string> parseProbes(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ',');) {
    if (std::find(kProbes.begin(), kProbes.end(), p) == kProbes.end())
      throw Error("--probe '" + p + "' is not one of: energy, overlap, front, height");
    out.push_back(p);
  }
  return out;
}

int validate(const std::string& sceneName, const std::string& probeText, int every, double until,
             const std::string& csvPath, const std::string& backend) {
  const std::vector<std::string> probes = parseProbes(probeText);
  const Scene scene = loadScene(resolveScenePath(sceneName));
  if (scene.model != "balls")
    throw Error("validate runs balls scenes; '" + scene.name + "' is a " + scene.model + " scene");
  const balls::Params params = ballsParams(scene);
  auto context = gl::createHeadlessContext({gl::parseBackend(backend), false});
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  balls::Balls model(shaders, params);
  // Scales of the dam-break probes: the initial column's width a and height h0.
  const bool column = params.fill == balls::Fill::Block;
  const glm::vec3 lo = column ? glm::max(params.fillMin, params.domainMin) : params.domainMin;
  const glm::vec3 hi = column ? glm::min(params.fillMax, params.domainMax) : params.domainMax;
  const double a = hi.x - lo.x, h0 = hi.z - lo.z;

  std::ofstream file;
  if (!csvPath.empty()) {
    file.open(csvPath);
    if (!file) throw Error("cannot write '" + csvPath + "'");
  }
  std::ostream& out = csvPath.empty() ? std::cout : file;
  auto has = [&](const char* p) { return std::find(probes.begin(), probes.end(), p) != probes.end(); };
  out << "time_s,count,nan";
  if (has("energy")) out << ",kinetic,potential,total";
  if (has("overlap")) out << ",max_overlap_r,mean_overlap_r";
  if (has("front")) out << ",front_over_a";
  if (has("height")) out << ",height_over_h0";
  out << "\n";
  int samples = 0;
  for (long step = 0;; ++step) {
    if (step % every == 0) {
      const balls::Stats s = model.stats();
      out << s.time << "," << s.count << "," << s.nonFinite;
      if (has("energy")) out << "," << s.kinetic << "," << s.potential << "," << s.kinetic + s.potential;
      if (has("overlap")) out << "," << s.maxOverlap << "," << s.meanOverlap;
      if (has("front")) out << "," << (s.front - params.domainMin.x + model.radius()) / a;  // ball surface
      if (has("height")) out << "," << (s.backHeight - params.domainMin.z + model.radius()) / h0;
      out << "\n";
      ++samples;
      if (s.nonFinite > 0)
        throw Error("balls diverged by t = " + std::to_string(s.time) + " s: " + std::to_string(s.nonFinite) +
                    " balls are NaN (see the CSV)");
    }
    if (model.time() >= until - 1e-12) break;
    model.stepOnce();
  }
  if (!csvPath.empty()) std::fprintf(stderr, "wrote %d samples to %s\n", samples, csvPath.c_str());
  return 0;
}

}  // namespace

Command addValidate(CLI::App& app) {
  auto* sub = app.add_subcommand("validate", "run a balls scene headless and write probe time series (CSV)");
  struct Opts {
    std::string scene, probes = "energy,overlap,front,height", csv, backend = "auto";
    int every = 100;
    double until = 1.0;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "balls scene file or name")->required();
  sub->add_option("--probe", o->probes, "comma list of energy, overlap, front, height");
  sub->add_option("--every", o->every, "steps between samples")->check(CLI::Range(1, 100000000));
  sub->add_option("--until", o->until, "simulated seconds")->check(CLI::Range(0.0, 1e9));
  sub->add_option("--csv", o->csv, "output file (default: standard output)");
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  return {sub, [o] { return validate(o->scene, o->probes, o->every, o->until, o->csv, o->backend); }};
}

}  // namespace tidepool::cli
