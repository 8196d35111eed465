// `tidepool bench ripples --size 512..4096`: ms per wave step and effective GB/s against a
// compute-shader copy (gl::BufferOps) of the same state bytes measured in the same run, plus both views at 1080p
// (the 3D frame includes the caustics pass), drawn by the compute renderers (`--renderer raster`:
// the raster ones they replaced, for comparison).
#include <cmath>
#include <cstdio>

#include "base/progress.h"
#include "bench/bench.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/framebuffer.h"
#include "render/ripples_view.h"
#include "render/ripples_view3d.h"
#include "sim/ripples/ripples.h"

namespace tidepool::bench {
namespace {

int run(Env& env, const std::string& sizes, bool raster) {
  constexpr int kStepsPerSample = 10;
  std::printf("ripples benchmark on %s (wave rule, C = 0.5, %d steps per sample, medians of %d; %s views)\n",
              env.device.c_str(), kStepsPerSample, env.common.repeats, raster ? "raster" : "compute");
  Table table({"cells", "ms/step", "GB/s", "copy GB/s", "% of copy", "2D view 1080p ms", "3D+caustics 1080p ms"});
  RenderTarget target(1920, 1080);
  RipplesView view(env.shaders);
  RipplesView3D view3d(env.shaders);
  const RipplesRenderer renderer = raster ? RipplesRenderer::Raster : RipplesRenderer::Compute;
  view.params().renderer = renderer;
  view3d.params().renderer = renderer;
  gl::GpuProfiler noProfiler;
  noProfiler.setEnabled(false);
  Steps steps("bench ripples", int(parseSizes(sizes).size()));
  for (std::size_t size : parseSizes(sizes)) {
    steps.begin(std::to_string(size) + "^2 cells");
    ripples::Params p;
    p.width = p.height = int(size);
    p.velDamping = 0.1f;
    ripples::Ripples model(env.shaders, p);
    model.touch(0.5f, 0.5f, 0.1f, -0.05f);
    const double dt = 0.5 * p.cellSize / p.waveSpeed;
    const double stepMs = gpuMedianMs(env.common,
                                      [&] {
                                        for (int i = 0; i < kStepsPerSample; ++i) model.stepOnce(dt);
                                      }) /
                          kStepsPerSample;
    // One step reads and writes the (h, v) state once: 16 bytes per cell.
    const double bytes = double(size) * size * 16.0;
    const gl::Buffer& state = model.state();
    gl::Buffer copy(state.size());
    const gl::BufferOps ops(env.shaders);
    const double copyMs = gpuMedianMs(env.common, [&] { ops.copy(state, copy, state.size()); });
    const double viewMs = gpuMedianMs(env.common, [&] { view.render(model, target, noProfiler); });
    const double view3dMs = gpuMedianMs(env.common, [&] { view3d.render(model, target, noProfiler); });
    const double gbps = bytes / (stepMs * 1e6), copyGbps = bytes / (copyMs * 1e6);
    table.add({std::to_string(size) + "^2", fixed(stepMs, 4), fixed(gbps, 1), fixed(copyGbps, 1),
               fixed(100.0 * gbps / copyGbps, 1), fixed(viewMs, 4), fixed(view3dMs, 4)});
  }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addRipplesBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("ripples", "heightfield wave step: ms/step, GB/s vs copy, 2D view at 1080p");
  auto sizes = std::make_shared<std::string>("512..4096");
  auto renderer = std::make_shared<std::string>("compute");
  sub->add_option("--size", *sizes, "grid edges, e.g. 512..4096 or 256,1024");
  sub->add_option("--renderer", *renderer, "views drawn by compute passes or by the raster pipeline")
      ->check(CLI::IsMember({"compute", "raster"}))
      ->capture_default_str();
  return {sub, [sizes, renderer](Env& env) { return run(env, *sizes, *renderer == "raster"); }};
}

}  // namespace tidepool::bench
