#include "render/swarm_renderer.h"

#include <algorithm>
#include <cmath>

#include "gl/kernel.h"
#include "render/swarm/bindings.glsl"
#include "swarm/bindings.glsl"

namespace tidepool {
namespace {

std::vector<gl::ShaderDefine> storageDefine(const sim::Swarm& swarm) {
  return {{"STORAGE_FP16", swarm.storage() == sim::Storage::Fp16 ? "1" : "0"}};
}

struct ColorUniforms {
  GLuint count = 0;
  GLint image = SWARM_IMAGE_UNIT;  // texture unit
  static constexpr auto fields() {
    return std::tuple{gl::field("uCount", &ColorUniforms::count), gl::field("uImage", &ColorUniforms::image)};
  }
};
struct SplatUniforms {
  GLuint count = 0;
  glm::ivec2 size{0};   // target pixels
  GLint colorMode = 0;  // 0: single colour, 1: per-particle colour, 2: velocity hue
  static constexpr auto fields() {
    return std::tuple{gl::field("uCount", &SplatUniforms::count), gl::field("uSize", &SplatUniforms::size),
                      gl::field("uColorMode", &SplatUniforms::colorMode)};
  }
};
}  // namespace

void visit(ParamVisitor& v, SwarmViewParams& p) {
  v.choice({"color_mode", "Colours", "single colour, from an image at the start positions, or velocity direction"},
           p.colorMode, kSwarmColorModeNames);
  v.flag({"auto_hue", "Cycle hue", "single colour: hue cycles once a minute"}, p.autoHue);
  v.color({"color", "Colour", "single colour when the hue does not cycle"}, p.color);
  v.text({"image", "Image", "name in assets/textures or a PNG path (drop a file on the window)"}, p.image);
  v.integer({"point_size", "Point size", "pixels: 1 = points, 3-17 = round sprites"}, p.pointSize, 1, 17);
  v.flag({"blend", "Blending", "additive with opacity; off: opaque"}, p.blend);
  v.real({"opacity", "Opacity", "weight of one particle when blending"}, p.opacity, 0.001f, 1.0f);
  v.flag({"high_quality", "High quality", "count particles per pixel and tone map: no saturation"}, p.highQuality);
  v.flag({"compute_points", "Compute points",
          "1-px points splatted with atomics by a compute pass (fast); off: GL_POINTS"},
         p.computePoints);
  v.flag({"show_attractors", "Show attractors", "rings at the attractors"}, p.showAttractors);
}

glm::vec3 swarmHue(double cycles) {
  const double h = 6.0 * (cycles - std::floor(cycles));  // 0..6: six linear segments
  auto channel = [&](double centre) {
    double d = std::abs(h - centre);
    d = std::min(d, 6.0 - d);
    return float(0.2 + 0.8 * std::clamp(2.0 - d, 0.0, 1.0));
  };
  return {channel(0.0), channel(2.0), channel(4.0)};
}

SwarmRenderer::SwarmRenderer(gl::ShaderLibrary& shaders)
    : m_shaders(shaders), m_ops(shaders), m_points(gl::VertexArray::create()), m_empty(gl::VertexArray::create()) {}

void SwarmRenderer::colorFromImage(const sim::Swarm& swarm, const io::Image& image) {
  gl::Texture2D texture(image.width, image.height, GL_RGBA8);
  texture.upload(GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());  // top row first: t = 0 is the top
  texture.setFilter(GL_LINEAR, GL_LINEAR);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  if (!m_colors || m_colors.size() != swarm.count() * 4) m_colors = gl::Buffer(swarm.count() * 4);
  m_colorCount = swarm.count();
  const gl::Kernel<ColorUniforms> colorPass(m_shaders, "render/swarm/color_image.comp",
                                            {SWARM_STATE_BINDING, SWARM_COLOR_BINDING}, storageDefine(swarm));
  swarm.state().bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_STATE_BINDING);
  m_colors.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_COLOR_BINDING);
  texture.bind(SWARM_IMAGE_UNIT);
  colorPass.dispatchThreads(swarm.count(), {GLuint(swarm.count())});
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void SwarmRenderer::adoptColors(const sim::Swarm& swarm, gl::Buffer colors) {
  m_colors = std::move(colors);
  m_colorCount = swarm.count();
}

void SwarmRenderer::drawPoints(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor,
                               bool accumulate) {
  const bool perParticle = view.colorMode == SwarmColorMode::Image && hasColors(swarm);
  const int mode = perParticle ? 1 : view.colorMode == SwarmColorMode::Velocity ? 2 : 0;
  gl::Program& p = m_shaders.program({"render/swarm/points.vert", "render/swarm/points.frag"});
  p.use();
  p.set("uColorMode", mode);
  p.set("uColor", singleColor);
  p.set("uPointSize", float(view.pointSize));
  p.set("uRound", view.pointSize > 2 ? 1 : 0);
  p.set("uOpacity", view.blend ? view.opacity : 1.0f);
  p.set("uAccumulate", accumulate ? 1 : 0);

  // The state buffer is read in place as a vertex attribute: position xy, velocity zw.
  m_points.bind();
  glBindBuffer(GL_ARRAY_BUFFER, swarm.state().id());
  const bool half = swarm.storage() == sim::Storage::Fp16;
  glVertexAttribPointer(SWARM_ATTRIB_STATE, 4, half ? GL_HALF_FLOAT : GL_FLOAT, GL_FALSE,
                        GLsizei(sim::swarmBytesPerParticle(swarm.storage())), nullptr);
  glEnableVertexAttribArray(SWARM_ATTRIB_STATE);
  if (perParticle) {
    glBindBuffer(GL_ARRAY_BUFFER, m_colors.id());
    glVertexAttribPointer(SWARM_ATTRIB_COLOR, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, nullptr);
    glEnableVertexAttribArray(SWARM_ATTRIB_COLOR);
  } else {
    glDisableVertexAttribArray(SWARM_ATTRIB_COLOR);
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDrawArrays(GL_POINTS, 0, GLsizei(swarm.count()));
  glBindVertexArray(0);
}

void SwarmRenderer::drawMarkers(std::span<const SwarmMarker> markers) {
  if (markers.empty()) return;
  std::vector<glm::vec4> packed;
  for (const SwarmMarker& m : markers) packed.emplace_back(m.ndc, m.strength, 0.0f);
  gl::Program& p = m_shaders.program({"render/swarm/markers.vert", "render/swarm/markers.frag"});
  p.use();
  glProgramUniform4fv(p.id(), p.uniform("uMarkers[0]"), GLsizei(packed.size()), &packed[0].x);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  m_empty.bind();
  glDrawArrays(GL_POINTS, 0, GLsizei(packed.size()));
  glBindVertexArray(0);
}

void SwarmRenderer::splatPoints(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor,
                                RenderTarget& target, gl::GpuProfiler& profiler) {
  const glm::ivec2 size(target.width(), target.height());
  const std::size_t bytes = std::size_t(size.x) * std::size_t(size.y) * 16;
  const bool perParticle = view.colorMode == SwarmColorMode::Image && hasColors(swarm);
  const int colorMode = perParticle ? 1 : view.colorMode == SwarmColorMode::Velocity ? 2 : 0;
  {
    auto scope = profiler.scope("swarm.splat");
    if (m_splat.size() != bytes) m_splat = gl::Buffer(bytes);
    m_ops.fill(m_splat, 0);
    const gl::Kernel<SplatUniforms> splat(m_shaders, "render/swarm/splat.comp",
                                          {SWARM_STATE_BINDING, SWARM_COLOR_BINDING, SWARM_SPLAT_BINDING},
                                          storageDefine(swarm));
    swarm.state().bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_STATE_BINDING);
    if (perParticle) m_colors.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_COLOR_BINDING);
    m_splat.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_SPLAT_BINDING);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // the clear before the atomics
    splat.dispatchThreads(swarm.count(), {GLuint(swarm.count()), size, colorMode});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  auto scope = profiler.scope("swarm.resolve");
  target.bind();
  glDisable(GL_BLEND);
  gl::Program& p = m_shaders.program({"render/common/fullscreen.vert", "render/swarm/splat_resolve.frag"});
  p.use();
  p.set("uSize", size);
  p.set("uMode", !view.blend ? 1 : view.highQuality ? 2 : 0);
  p.set("uSingle", colorMode == 0 ? 1 : 0);
  p.set("uColor", singleColor);
  p.set("uOpacity", view.opacity);
  m_splat.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_SPLAT_BINDING);
  m_empty.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void SwarmRenderer::render(const sim::Swarm& swarm, const SwarmViewParams& view, glm::vec3 singleColor,
                           std::span<const SwarmMarker> markers, RenderTarget& target, gl::GpuProfiler& profiler) {
  glDisable(GL_DEPTH_TEST);
  if (view.pointSize == 1 && view.computePoints) {
    splatPoints(swarm, view, singleColor, target, profiler);
  } else if (view.highQuality) {
    {
      auto scope = profiler.scope("swarm.accumulate");
      if (m_accum.width() != target.width() || m_accum.height() != target.height()) {
        m_accum = gl::Texture2D(target.width(), target.height(), GL_RGBA32F);
        m_accumFbo = gl::Framebuffer({&m_accum});
      }
      m_accumFbo.bind();
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      drawPoints(swarm, view, singleColor, true);
    }
    auto scope = profiler.scope("swarm.tonemap");
    target.bind();
    glDisable(GL_BLEND);
    gl::Program& p = m_shaders.program({"render/common/fullscreen.vert", "render/swarm/tonemap.frag"});
    p.use();
    p.set("uOpacity", view.blend ? view.opacity : -1.0f);
    m_accum.bind(SWARM_VIEW_ACCUM_UNIT);
    m_empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  } else {
    auto scope = profiler.scope("swarm.points");
    target.bind();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (view.blend) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    } else {
      glDisable(GL_BLEND);
    }
    drawPoints(swarm, view, singleColor, false);
  }
  if (view.showAttractors) drawMarkers(markers);
  glDisable(GL_BLEND);
  glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace tidepool
