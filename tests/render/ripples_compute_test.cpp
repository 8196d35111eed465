// The compute renderers of the ripples views (the 2D compute pass, the caustics splat, the 3D
// ray caster) draw the pictures the raster renderers draw: same scene, both renderers, images
// compared pixel by pixel. Set TIDEPOOL_TEST_IMAGES=<folder> to keep the images as PNGs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "io/png.h"
#include "render/ripples_view.h"
#include "render/ripples_view3d.h"
#include "support/gl_test.h"
#include "support/image_diff.h"

using namespace tidepool;

namespace {

class RipplesCompute : public test::GlTest {};

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
  const test::PixelDifference d = test::pixelDifference(raster, compute, 16);
  std::cout << name << ": mean |diff| " << d.mean << "/255, " << 100.0 * d.offFraction
            << "% of pixels off by > 16/255, max " << d.maxAbs << "/255\n";
  EXPECT_LE(d.mean, 2.0) << name;
  EXPECT_LE(d.offFraction, 0.01) << name;
}

// Draws the model with the view's raster renderer, then its compute renderer, and compares.
template <class View>
void expectComputeMatchesRaster(const std::string& name, View& view, const ripples::Ripples& model,
                                RenderTarget& target, gl::GpuProfiler& profiler) {
  view.params().renderer = RipplesRenderer::Raster;
  view.render(model, target, profiler);
  const std::vector<uint8_t> raster = target.readRgba8();
  view.params().renderer = RipplesRenderer::Compute;
  view.render(model, target, profiler);
  expectClose(name, target, raster, target.readRgba8());
}

// A 64x48 pool with a few drops' rings, optionally the ball circling through it.
std::unique_ptr<ripples::Ripples> wavyPool(gl::ShaderLibrary& shaders, bool withBall, gl::GpuProfiler& profiler) {
  ripples::Params p;
  p.width = 64;
  p.height = 48;  // not square: the tank's y extent and the cover mapping matter
  p.sphere = withBall;
  p.sphereRadius = 0.12f;  // m; the tank is 1.28 m across
  p.sphereHeight = 0.03f;
  p.frameSeconds = 1.0 / 60;
  auto model = std::make_unique<ripples::Ripples>(shaders, p);
  model->touch(0.35f, 0.55f, 0.15f, -0.05f);
  model->touch(0.7f, 0.35f, 0.1f, -0.04f);
  for (int i = 0; i < 12; ++i) model->step(profiler);
  return model;
}

// The wavy pool without and with the ball, each drawn into a `size` target by both renderers of a
// fresh view (setUp tunes it) and compared; `name` names the images (name, name-ball).
template <class View>
void expectComputeMatchesRasterOnBothPools(gl::ShaderLibrary& shaders, const std::string& name, glm::ivec2 size,
                                           void (*setUp)(View&)) {
  gl::GpuProfiler profiler;
  for (const bool withBall : {false, true}) {
    const auto pool = wavyPool(shaders, withBall, profiler);
    View view(shaders);
    setUp(view);
    RenderTarget target(size.x, size.y);
    expectComputeMatchesRaster(withBall ? name + "-ball" : name, view, *pool, target, profiler);
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

std::vector<float> lightOf(const RipplesView3D& view) {
  std::vector<float> light(std::size_t(view.caustics().width()) * view.caustics().height());
  view.caustics().download(GL_RED, GL_FLOAT, light.data());
  return light;
}

}  // namespace

TEST_F(RipplesCompute, TopViewMatchesTheRasterView) {
  expectComputeMatchesRasterOnBothPools<RipplesView>(shaders(), "ripples-2d", {200, 120}, [](RipplesView&) {});
}

TEST_F(RipplesCompute, CausticsSplatLandsLikeThePoints) {
  gl::GpuProfiler profiler;
  const auto pool = wavyPool(shaders(), false, profiler);
  const ripples::Ripples& model = *pool;
  RipplesView3D view(shaders());
  view.params().lightGrid = 128;
  view.params().causticsSize = 64;
  RenderTarget target(32, 32);
  view.params().renderer = RipplesRenderer::Raster;
  view.render(model, target, profiler);
  const std::vector<float> raster = lightOf(view);
  view.params().renderer = RipplesRenderer::Compute;
  view.render(model, target, profiler);
  const std::vector<float> compute = lightOf(view);
  ASSERT_EQ(raster.size(), compute.size());
  double maxDiff = 0, sumRaster = 0, sumCompute = 0;
  int off = 0;
  for (std::size_t i = 0; i < raster.size(); ++i) {
    maxDiff = std::max(maxDiff, double(std::abs(raster[i] - compute[i])));
    off += std::abs(raster[i] - compute[i]) > 1e-2f;
    sumRaster += raster[i];
    sumCompute += compute[i];
  }
  std::cout << "caustics: " << off << " of " << raster.size() << " texels differ, max by " << maxDiff << "; light "
            << sumRaster << " (raster) " << sumCompute << " (compute)\n";
  // Points within a rounding error of a texel edge may land on either side: the raster snaps
  // them to its sub-pixel grid first. One light point carries 64 x 48 / (128 x 96) = 0.25.
  EXPECT_LT(off, int(raster.size()) / 20) << "nearly all points land in the same texels";
  EXPECT_LE(maxDiff, 2 * 0.25 + 1e-3) << "and the others next door";
  EXPECT_NEAR(sumCompute, double(compute.size()), 1e-6 * double(compute.size())) << "every point lands once";
  EXPECT_GT(*std::max_element(compute.begin(), compute.end()), 1.5f) << "the waves should focus light";
  // A second frame starts from cleared counters.
  view.render(model, target, profiler);
  EXPECT_EQ(lightOf(view), compute);
}

TEST_F(RipplesCompute, TankViewMatchesTheRasterView) {
  expectComputeMatchesRasterOnBothPools<RipplesView3D>(shaders(), "ripples-3d", {240, 160}, [](RipplesView3D& view) {
    view.params().lightGrid = 256;
    view.params().causticsSize = 128;
  });
}

TEST_F(RipplesCompute, TankViewFromOtherAnglesMatchesTheRasterView) {
  gl::GpuProfiler profiler;
  const auto pool = wavyPool(shaders(), true, profiler);
  const ripples::Ripples& model = *pool;
  RipplesView3D view(shaders());
  view.params().exaggeration = 12.0f;  // steep waves: grazing rays, surfaces seen edge-on
  RenderTarget target(240, 160);
  const float angles[][2] = {{2.2f, 0.25f}, {-2.5f, 1.2f}, {0.4f, 0.08f}};  // yaw, pitch
  for (const auto& a : angles) {
    view.camera().params().yaw = a[0];
    view.camera().params().pitch = a[1];
    expectComputeMatchesRaster("ripples-3d-yaw" + std::to_string(a[0]) + "-pitch" + std::to_string(a[1]), view, model,
                               target, profiler);
  }
}

TEST_F(RipplesCompute, OrthographicTankViewMatchesTheRasterView) {
  // Parallel rays: the ray caster starts them on the near plane, the raster projects with glm::ortho.
  gl::GpuProfiler profiler;
  const auto pool = wavyPool(shaders(), true, profiler);
  RipplesView3D view(shaders());
  view.camera().params().projection = Projection::Orthographic;
  RenderTarget target(240, 160);
  for (const float pitch : {0.62f, 1.3f}) {
    view.camera().params().pitch = pitch;
    expectComputeMatchesRaster("ripples-3d-ortho-pitch" + std::to_string(pitch), view, *pool, target, profiler);
  }
}
