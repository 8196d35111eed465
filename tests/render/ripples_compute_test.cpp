// The compute renderers of the ripples views (the 2D compute pass) draw the pictures the raster
// renderers draw: same scene, both renderers, images compared pixel by pixel.
// Set TIDEPOOL_TEST_IMAGES=<folder> to keep the images as PNGs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "io/png.h"
#include "render/ripples_view.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class RipplesCompute : public test::GlTest {};

struct ImageDiff {
  double meanAbs = 0;  // mean |a - b| over the RGB channels, in 1/255
  double farOff = 0;   // fraction of pixels where some channel differs by more than 16/255
  int maxAbs = 0;      // in 1/255
};

ImageDiff compare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  ImageDiff d;
  std::size_t far = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a[i + c]) - int(b[i + c]));
      d.meanAbs += e;
      worst = std::max(worst, e);
    }
    far += worst > 16;
    d.maxAbs = std::max(d.maxAbs, worst);
  }
  d.meanAbs /= 3.0 * double(a.size() / 4);
  d.farOff = double(far) / double(a.size() / 4);
  return d;
}

void keep(const std::string& name, const RenderTarget& target, const std::vector<uint8_t>& rgba) {
  if (const char* dir = std::getenv("TIDEPOOL_TEST_IMAGES"))
    io::writePng(std::filesystem::path(dir) / (name + ".png"), io::Image{target.width(), target.height(), rgba});
}

void expectClose(const std::string& name, const RenderTarget& target, const std::vector<uint8_t>& raster,
                 const std::vector<uint8_t>& compute) {
  keep(name + "-raster", target, raster);
  keep(name + "-compute", target, compute);
  std::vector<uint8_t> diff(raster.size(), 255);  // |raster - compute| x 4
  for (std::size_t i = 0; i < diff.size(); ++i)
    if (i % 4 != 3) diff[i] = uint8_t(std::min(255, 4 * std::abs(int(raster[i]) - int(compute[i]))));
  keep(name + "-diff", target, diff);
  const ImageDiff d = compare(raster, compute);
  std::cout << name << ": mean |diff| " << d.meanAbs << "/255, " << 100.0 * d.farOff
            << "% of pixels off by > 16/255, max " << d.maxAbs << "/255\n";
  EXPECT_LE(d.meanAbs, 2.0) << name;
  EXPECT_LE(d.farOff, 0.01) << name;
}

// A 64x48 pool with a few drops' rings, optionally the ball circling through it.
std::unique_ptr<ripples::Ripples> wavyPool(gl::ShaderLibrary& shaders, bool withBall, gl::GpuProfiler& profiler) {
  ripples::Params p;
  p.width = 64;
  p.height = 48;  // not square: the tank's y extent and the cover mapping matter
  p.sphere = withBall;
  p.sphereRadius = 0.12f;  // m; the tank is 1.28 m across
  p.sphereHeight = 0.03f;
  auto model = std::make_unique<ripples::Ripples>(shaders, p);
  model->touch(0.35f, 0.55f, 0.15f, -0.05f);
  model->touch(0.7f, 0.35f, 0.1f, -0.04f);
  for (int i = 0; i < 12; ++i) model->step(1.0 / 60, profiler);
  return model;
}

}  // namespace

TEST_F(RipplesCompute, TopViewMatchesTheRasterView) {
  gl::GpuProfiler profiler;
  for (const bool withBall : {false, true}) {
    const auto pool = wavyPool(shaders(), withBall, profiler);
    const ripples::Ripples& model = *pool;
    RipplesView view(shaders());
    RenderTarget target(200, 120);
    view.params().renderer = RipplesRenderer::Raster;
    view.render(model, target, profiler);
    const std::vector<uint8_t> raster = target.readRgba8();
    view.params().renderer = RipplesRenderer::Compute;
    view.render(model, target, profiler);
    expectClose(withBall ? "ripples-2d-ball" : "ripples-2d", target, raster, target.readRgba8());
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
