// `tidepool soak <scene> --steps N --every K`: a long headless run of a scene (sweep/soak.h) that
// prints one row per sample (step, simulated and wall time, RSS, particles, energy) and exits 1
// with one line naming what failed: RSS growth after warm-up, a particle lost or NaN, an energy
// beyond its bound, or a divergence report. docs/RELIABILITY.md ("Long runs") has the results.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "gl/context.h"
#include "sweep/soak.h"

namespace tidepool::cli {
namespace {

int soakScene(const std::string& sceneName, const sweep::SoakRun& run, const sweep::SoakLimits& limits,
              const std::string& backend) {
  const Scene scene = loadScene(resolveScenePath(sceneName));
  auto context = gl::createHeadlessContext({gl::parseBackend(backend), false});
  gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
  const long every = run.every > 0 ? run.every : std::max(1L, run.steps / 20);
  std::printf("soak: %s (%s), %ld frames, a sample every %ld\n", scene.name.c_str(), scene.model.c_str(), run.steps,
              every);
  std::printf("%9s %10s %9s %9s %9s %9s %12s\n", "frame", "time_s", "wall_s", "rss_MiB", "count", "held", "energy");
  const sweep::SoakResult r = sweep::soak(scene, shaders, run, [](const sweep::SoakSample& s) {
    std::printf("%9ld %10.3f %9.1f %9.1f %9zu %9zu %12.5g\n", s.step, s.time, s.wallSeconds, s.rssMiB, s.count, s.held,
                s.energy);
    std::fflush(stdout);
  });
  const std::vector<std::string> failures = sweep::judgeSoak(r.samples, limits);
  double maxEnergy = 0;
  for (const sweep::SoakSample& s : r.samples) maxEnergy = std::max(maxEnergy, s.energy);
  const sweep::SoakSample &first = r.samples.front(), &last = r.samples.back();
  std::printf("energy: %s; largest %.5g\n", r.energyName.c_str(), maxEnergy);
  if (!failures.empty()) {
    std::string all;
    for (const std::string& f : failures) all += (all.empty() ? "" : "; ") + f;
    throw Error("soak of '" + scene.name + "' failed: " + all);
  }
  std::printf("soak: held for %ld steps in %.1f s: RSS %.1f -> %.1f MiB, %zu held, no NaN, energy bounded\n", last.step,
              last.wallSeconds, first.rssMiB, last.rssMiB, last.held);
  return 0;
}

}  // namespace

Command addSoak(CLI::App& app) {
  auto* sub = app.add_subcommand("soak", "run a scene headless for many steps, checking memory, particles and energy");
  struct Opts {
    std::string scene, backend = "auto";
    sweep::SoakRun run;
    sweep::SoakLimits limits;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "scene file or name (its model: balls, fluid, life, swarm or ripples)")
      ->required();
  sub->add_option("--steps", o->run.steps, "frames to step (one step each where the scene has one substep)")
      ->check(CLI::Range(1L, 1000000000L));
  sub->add_option("--every", o->run.every, "steps between samples (default: steps / 20)")
      ->check(CLI::Range(1L, 1000000000L));
  sub->add_option("--warmup", o->limits.warmup, "fraction of the steps before the baselines (default 0.1)")
      ->check(finiteRange(0.0, 0.9));
  sub->add_option("--rss-tolerance", o->limits.rssGrowthMiB, "MiB the RSS may grow after warm-up (default 4)")
      ->check(finiteRange(0.0, 1e6));
  sub->add_option("--energy-factor", o->limits.energyFactor, "energy bound, times the warm-up's largest (default 10)")
      ->check(finiteRange(1.0, 1e12));
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  return {sub, [o] { return soakScene(o->scene, o->run, o->limits, o->backend); }};
}

}  // namespace tidepool::cli
