// The ripples views draw real pictures; caustics conserve light (flat water lights the floor
// evenly with 1; waves focus it without creating or losing any).
#include <gtest/gtest.h>

#include <numeric>

#include "render/ripples_view.h"
#include "render/ripples_view3d.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class RipplesViews : public test::GlTest {};

ripples::Params smallPool() {
  ripples::Params p;
  p.width = p.height = 64;
  return p;
}

std::vector<float> causticsOf(RipplesView3D& view) {
  std::vector<float> light(std::size_t(view.caustics().width()) * view.caustics().height());
  view.caustics().download(GL_RED, GL_FLOAT, light.data());
  return light;
}

// A drop of `radius` (grid units) at (x, y), spread for `frames` frames of 1/60 s.
void dropAndWait(ripples::Ripples& model, float x, float y, float radius, int frames, gl::GpuProfiler& profiler) {
  model.touch(x, y, radius, -0.05f);
  model.params().frameSeconds = 1.0 / 60;
  for (int i = 0; i < frames; ++i) model.step(profiler);
}

int distinctColours(const std::vector<uint8_t>& rgba) {
  std::vector<uint32_t> c;
  for (std::size_t i = 0; i < rgba.size(); i += 4) c.push_back(rgba[i] | rgba[i + 1] << 8 | rgba[i + 2] << 16);
  std::sort(c.begin(), c.end());
  return int(std::unique(c.begin(), c.end()) - c.begin());
}

}  // namespace

TEST_F(RipplesViews, FlatWaterLightsTheFloorEvenly) {
  ripples::Ripples model(shaders(), smallPool());
  RenderTarget target(64, 48);
  gl::GpuProfiler profiler;
  for (const RipplesRenderer renderer : {RipplesRenderer::Compute, RipplesRenderer::Raster})
    for (const bool caustics : {true, false}) {
      RipplesView3D view(shaders());
      view.params().lightGrid = 128;
      view.params().causticsSize = 64;
      view.params().renderer = renderer;
      view.params().caustics = caustics;  // off: the floor gets the flat-water light without tracing it
      view.render(model, target, profiler);
      const std::vector<float> light = causticsOf(view);
      ASSERT_EQ(light.size(), 64u * 64u);
      for (float l : light) ASSERT_NEAR(l, 1.0f, 1e-3f) << kRipplesRendererNames[int(renderer)];
    }
}

TEST_F(RipplesViews, WavesFocusLightWithoutCreatingOrLosingIt) {
  ripples::Ripples model(shaders(), smallPool());
  gl::GpuProfiler profiler;
  dropAndWait(model, 0.5f, 0.5f, 0.2f, 20, profiler);
  RenderTarget target(64, 48);
  for (const RipplesRenderer renderer : {RipplesRenderer::Compute, RipplesRenderer::Raster}) {
    RipplesView3D view(shaders());
    view.params().lightGrid = 128;
    view.params().causticsSize = 64;
    view.params().renderer = renderer;
    view.render(model, target, profiler);
    const std::vector<float> light = causticsOf(view);
    const double mean = std::accumulate(light.begin(), light.end(), 0.0) / double(light.size());
    const char* name = kRipplesRendererNames[int(renderer)];
    EXPECT_NEAR(mean, 1.0, 2e-3) << name << ": every light point lands on the floor (wrapped), so the mean stays 1";
    EXPECT_GT(*std::max_element(light.begin(), light.end()), 1.5f) << name << ": the waves should focus light";
    EXPECT_LT(*std::min_element(light.begin(), light.end()), 0.7f) << name << ": and leave darker bands";
  }
}

TEST_F(RipplesViews, BothViewsDrawTheWaterNotAFlatColour) {
  ripples::Ripples model(shaders(), smallPool());
  gl::GpuProfiler profiler;
  dropAndWait(model, 0.4f, 0.5f, 0.15f, 10, profiler);
  RenderTarget target(96, 64);
  RipplesView top(shaders());
  top.render(model, target, profiler);
  EXPECT_GT(distinctColours(target.readRgba8()), 50);
  RipplesView3D tank(shaders());
  tank.render(model, target, profiler);
  const std::vector<uint8_t> px = target.readRgba8();
  EXPECT_GT(distinctColours(px), 50);
  // The tank sits in the middle of the frame; the corners show the background.
  EXPECT_EQ(px[0], px[(96 * 64 - 1) * 4]);
  EXPECT_NE(px[(32 * 96 + 48) * 4 + 2], px[2]) << "the centre pixel should be water, not background";
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
