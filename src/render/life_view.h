// Renderer of the life model, after lisyarus' particle life (shared/SEEDS.md 5.5): particles are
// added into an RGBA16F HDR image — a Gaussian glow, then either antialiased discs (a 1-px
// analytic edge) when a particle covers at least a pixel per world unit, or a sub-pixel
// coverage splat that keeps each particle's total brightness when zoomed out (no flicker) —
// then composed into the target: ACES filmic tone map, gamma 2.2 and blue-noise dithering to
// 8 bits. Reads the model's buffers; writes only its HDR image and the target.
#pragma once

#include "base/param.h"
#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/target.h"
#include "sim/life/life.h"

namespace tidepool {

struct LifeViewParams {
  bool glow = true;        // the Gaussian halo pass
  bool particles = true;   // the disc / sub-pixel pass
  float glowSize = 12.0f;  // half-size of the glow quad (world units); alpha = exp(-6 |o|^2) / 64
  float glowIntensity = 1.0f / 64.0f;
  float radius = 1.0f;    // particle disc radius (world units)
  float exposure = 1.0f;  // HDR scale before the tone map
  bool dither = true;     // blue-noise dither to 8 bits (off: round to nearest)
};
void visit(ParamVisitor& v, LifeViewParams& p);

// A 2D camera: the world point at the image centre and half the visible width, and where the
// wheel's zoom is gliding to (as the original: the extent eases toward its target at 20/s while
// the world point under the cursor of the last wheel step stays under it).
struct LifeCamera {
  glm::vec2 centre{0.0f};       // world units
  float extentX = 512.0f;       // half the visible width (world units); the height follows the aspect
  float targetExtentX = 0.0f;   // where the zoom glides to (0: no glide)
  glm::vec2 anchorPixel{0.0f};  // cursor of the last wheel step (pixels, origin top-left)
  glm::vec2 anchorWorld{0.0f};  // the world point kept under it while gliding
};
constexpr float kZoomEaseRate = 20.0f;  // 1/s: extent += (target - extent)(1 - exp(-rate dt))

class LifeView {
 public:
  explicit LifeView(gl::ShaderLibrary& shaders);
  LifeViewParams& params() { return m_params; }
  LifeCamera& camera() { return m_camera; }
  void render(const life::Life& model, RenderTarget& target, gl::GpuProfiler& profiler);

  // Fits the whole box into an image of this size (the article's "Center view").
  static LifeCamera fit(glm::vec2 boxSize, glm::ivec2 viewport);
  glm::vec2 toWorld(glm::vec2 pixel, glm::ivec2 viewport) const;  // pixel: origin top-left
  // Right drag: the world point that was under cursor - delta moves to the cursor.
  void pan(glm::vec2 cursor, glm::vec2 delta, glm::ivec2 viewport);
  // Wheel: the target extent *= 1.25^-clicks (in when positive), anchored at the cursor; the
  // extent then glides there (glide()), the world point under the cursor fixed.
  void zoomAbout(glm::vec2 cursor, float clicks, glm::ivec2 viewport);
  void glide(float seconds, glm::ivec2 viewport);  // eases the extent toward the target, once a frame
  bool gliding() const { return m_camera.targetExtentX > 0.0f; }
  float pixelsPerUnit(int imageWidth) const { return float(imageWidth) / (2.0f * m_camera.extentX); }
  const gl::Texture2D& hdr() const { return m_hdr; }  // the last frame before the tone map (tests)

 private:
  void drawParticles(const life::Life& model, const char* fragment, float halfSize, float ppu, glm::vec2 extent);

  gl::ShaderLibrary& m_shaders;
  LifeViewParams m_params;
  LifeCamera m_camera;
  gl::Texture2D m_hdr, m_blueNoise;
  gl::Framebuffer m_hdrFbo;
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
