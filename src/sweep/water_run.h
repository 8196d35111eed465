// The two water models stepped, timed and sampled alike for the water studies
// (water_studies.cpp: fluid-density and water-front; fluid_stability_study.cpp): one run of the
// balls (DEM) or of the fluid (PBF) on the same water, read on the same metrics. The density error
// is measured with the fluid's kernel for both (fluid::DensityProbe; the balls with h = 2 × their
// spacing 2r on the HCP lattice they fill), the surge front as `tidepool validate --probe front`
// computes it, the health as the divergence watch judges it.
//
//   WaterRun run(shaders, fluidParams);
//   run.advanceTo(0.4);                  // timed steps, counted (no drift of a float clock)
//   const WaterSample s = run.sample();  // blocking
//   double cost = run.gpuMs() / run.time();
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/density_probe.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool::balls {
class Balls;
}
namespace tidepool::fluid {
class Fluid;
}
namespace tidepool::sim {
class Model;
}

namespace tidepool::sweep {

// GPU ms of `steps` calls of `step`, in chunks (GL timer queries; wall clock between glFinish
// calls on a software renderer): balls_studies.cpp.
double timedSteps(long steps, const std::function<void()>& step);

// The RMS of (front − Z) over the points of Martin & Moyce's measured dam-break front (1952, fig. 3,
// n² = 2: Z = z/a against T = t·sqrt(2g/a)) inside a run's front, sampled every `every` s in
// column widths a (m) under gravity g (m/s²), linearly interpolated from 1 at t = 0; `points`
// gets how many of their points the run reached (NaN when none).
double rmsFromMartinMoyce(const std::vector<double>& front, double every, double a, double g, int& points);

struct WaterSample {
  double time = 0;             // simulated s
  double compressionMean = 0;  // mean of max(ρ/ρ0 − 1, 0) with the fluid's kernel: the density error
  double compressionMax = 0;   // max of ρ/ρ0 − 1
  double front = 0;            // (front + r − domain min x) / a: the surge front in column widths (NaN: none)
  double maxSpeed = 0;         // m/s
  bool healthy = true;         // no NaN, none outside the walls, none faster than speedBound()
};

class WaterRun {
 public:
  WaterRun(gl::ShaderLibrary& shaders, const balls::Params& params);  // balls, one step per frame
  WaterRun(gl::ShaderLibrary& shaders, const fluid::Params& params);  // fluid, one step per frame
  ~WaterRun();

  // Steps until the step count reaches round(t / dt), timed. `watched`: each step is a frame of
  // the model (sim::Model::step) so that its divergence watch checks it (every 8 steps); its
  // first report stops the run there (divergence(); time() stays at the last step taken).
  void advanceTo(double t, bool watched = false);
  WaterSample sample(bool density = true);                // blocking: the model's statistics (and the density probe)
  std::optional<std::string> divergence();                // the watch's report (waits for the check in flight)
  double time() const { return double(m_steps) * m_dt; }  // s, the steps taken × dt
  double dt() const { return m_dt; }                      // s
  double gpuMs() const { return m_ms; }                   // of all steps taken
  double speedBound() const;  // m/s: faster moves more than the neighbour reach per step (fluid h, balls 2r)
  std::size_t count() const;
  double spacing() const { return 2.0 * m_radius; }  // m: the fluid's d, the balls' 2r
  double columnWidth() const { return m_width; }     // m: the dam-break column's a, the front's unit

 private:
  sim::Model& model();
  void stepFrame(bool watched);

  std::unique_ptr<balls::Balls> m_balls;
  std::unique_ptr<fluid::Fluid> m_fluid;
  fluid::DensityProbe m_probe;
  gl::GpuProfiler m_profiler;  // disabled: the watched steps' frames time nothing
  water::Setup m_water;        // resolved: domain, fill, gravity
  double m_dt = 0, m_radius = 0, m_width = 0, m_ms = 0;
  long m_steps = 0;
  bool m_stopped = false;  // the watch reported
};

}  // namespace tidepool::sweep
