// Draws the swarm straight from the simulation's state buffer (bound as a vertex attribute
// buffer: vec4 for fp32 storage, 4 x GL_HALF_FLOAT for fp16; no CPU copy), as 1-px points or
// round sprites of 3-17 px:
//   - additive blending (src * opacity + dst) or opaque overwrite, into the RenderTarget;
//   - high quality: accumulate per-pixel (sum of colours, count) in an RGBA32F image, then tone
//     map brightness = 1 - exp(-opacity * count), so dense regions never clip at 255.
// 1-px points go through a compute splat by default (atomic per-pixel counters, then a resolve
// pass with the same three looks; opaque shows the pixel's mean colour): it skips the raster
// pipeline, the bottleneck for tens of millions of points. Sprites always use the raster path.
// Colours: one colour (fixed, or hue cycling once a minute), per particle from an image sampled
// at its start position (colorFromImage, after each reset), or from the velocity direction.
#pragma once

#include <array>
#include <span>
#include <string>

#include "base/param.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "io/png.h"
#include "render/target.h"
#include "sim/swarm/swarm.h"

namespace tidepool {

enum class SwarmColorMode { Single, Image, Velocity };
inline constexpr std::array<const char*, 3> kSwarmColorModeNames = {"single", "image", "velocity"};

struct SwarmViewParams {
  SwarmColorMode colorMode = SwarmColorMode::Single;
  bool autoHue = true;                      // single colour: cycle the hue once a minute
  glm::vec3 color{0.737f, 0.259f, 0.071f};  // single colour when autoHue is off (seed: #BC4212)
  std::string image = "colors";             // image mode: a name in assets/textures or a PNG path
  int pointSize = 1;                        // pixels: 1 = points, 3..17 = round sprites
  bool blend = true;                        // additive with opacity, else opaque
  float opacity = 0.1f;                     // per-particle weight when blending
  bool highQuality = false;                 // count per pixel and tone map (no saturation)
  bool computePoints = true;                // 1-px points: compute splat instead of GL_POINTS
  bool showAttractors = true;               // rings at the attractors
};
void visit(ParamVisitor& v, SwarmViewParams& p);

struct SwarmMarker {
  glm::vec2 ndc;   // position in the image, NDC
  float strength;  // sign picks the colour: attractive or repulsive
};

glm::vec3 swarmHue(double cycles);  // the seed's 6-segment hue ramp, minimum channel 0.2

class SwarmRenderer {
 public:
  explicit SwarmRenderer(gl::ShaderLibrary& shaders);

  // Per-particle colours (packUnorm4x8) from `image` stretched over the NDC box, sampled
  // (bilinear, clamped) at each particle's current position: call it right after a reset.
  void colorFromImage(const sim::Swarm& swarm, const io::Image& image);
  bool hasColors(const sim::Swarm& swarm) const { return m_colors && m_colorCount == swarm.count(); }
  const gl::Buffer& colors() const { return m_colors; }
  void adoptColors(const sim::Swarm& swarm, gl::Buffer colors);  // colours made earlier (a checkpoint's)

  // singleColor: the colour used in single mode (the caller resolves hue cycling).
  void render(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor,
              std::span<const SwarmMarker> markers, RenderTarget& target, gl::GpuProfiler& profiler);

 private:
  void drawPoints(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor, bool accumulate);
  void drawMarkers(std::span<const SwarmMarker> markers);
  void splatPoints(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor, RenderTarget& target,
                   gl::GpuProfiler& profiler);

  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;  // the splat clear
  gl::VertexArray m_points, m_empty;
  gl::Buffer m_colors;
  std::size_t m_colorCount = 0;
  gl::Texture2D m_accum;  // high quality: RGBA32F (sum of rgb, count)
  gl::Framebuffer m_accumFbo;
  gl::Buffer m_splat;  // compute points: (count, r, g, b) uints per pixel
};

}  // namespace tidepool
