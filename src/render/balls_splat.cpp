#include "render/balls_splat.h"

#include <algorithm>

#include "render/balls/bindings.glsl"

namespace tidepool {

namespace {
constexpr GLuint kBigHeader[4] = {0, 1, 1, 0};  // indirect groups (x, y, z), overflow flag
constexpr std::size_t kBigHeaderBytes = sizeof(kBigHeader);
}  // namespace

BallsSplat::BallsSplat(gl::ShaderLibrary& shaders) : m_shaders(shaders), m_ops(shaders) {}

void BallsSplat::resize(const BallsCamera& camera, std::size_t balls) {
  const std::size_t pixels = std::size_t(camera.width) * std::size_t(camera.height);
  if (m_keys.size() != pixels * 4) {
    // The resolve puts every pixel back to empty, so these are filled once per size.
    m_keys.resize(pixels * 4);
    m_thickness.resize(pixels * 4);
    m_ops.fill(m_keys, 0xFFFFFFFFu);
    m_ops.fill(m_thickness, 0u);
  }
  const unsigned capacity = unsigned(std::clamp<std::size_t>(balls, 1, kMaxBig));
  if (capacity > m_bigCapacity) {
    m_big.resize(kBigHeaderBytes + std::size_t(capacity) * 4);
    m_bigCapacity = capacity;
  }
}

void BallsSplat::setCommon(gl::Program& program, const SphereBatch& balls, const BallsCamera& camera) const {
  program.use();
  program.set("uModelView", camera.view * balls.model);
  program.set("uProjDepth", glm::vec2(camera.proj[2][2], camera.proj[3][2]));
  program.set("uFocal", glm::vec2(camera.proj[0][0], camera.proj[1][1]));
  program.set("uOrtho", camera.isOrthographic() ? 1 : 0);
  program.set("uSize", glm::ivec2(camera.width, camera.height));
  program.set("uRadius", balls.radius);
  program.set("uCount", unsigned(balls.count));
  program.set("uBigCapacity", m_bigCapacity);
  program.set("uThicknessUnit", balls.radius / kThicknessSteps);
  program.set("uThickness", m_thicknessOn ? 1 : 0);  // the depth pass's
  program.set("uScene", m_sceneOn ? 1 : 0);
  program.set("uSceneMin", m_sceneRect.min);
  program.set("uSceneMax", m_sceneRect.max);
}

void BallsSplat::perBall(const char* kernel, const SphereBatch& balls, const BallsCamera& camera) {
  const std::string file = std::string("render/balls/") + kernel + ".comp";
  gl::Program& small = m_shaders.program({file}, {{"BIG", "0"}});
  setCommon(small, balls, camera);
  small.dispatchThreads(balls.count);
  // The list and its group count are complete once the small kernel's writes are visible.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  gl::Program& big = m_shaders.program({file}, {{"BIG", "1"}});
  setCommon(big, balls, camera);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, m_big.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void BallsSplat::draw(const SphereBatch& balls, const BallsCamera& camera, const SceneDepth& scene, bool thickness,
                      const gl::Texture2D& surface, const gl::Texture2D& foam, const gl::Texture2D& depth,
                      gl::GpuProfiler& profiler) {
  resize(camera, balls.count);
  m_thicknessOn = thickness;
  m_sceneOn = scene.texture != nullptr;
  m_sceneRect = scene.rect;
  balls.positions->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_POSITIONS);
  if (balls.velocities) balls.velocities->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_VELOCITIES);
  m_keys.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_SPLAT_KEYS);
  m_thickness.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_SPLAT_THICKNESS);
  m_big.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_SPLAT_BIG);
  {
    auto scope = profiler.scope("balls.splat.depth");
    // The last frame's kernels wrote the header: make that visible before overwriting it.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    m_big.upload(kBigHeader, kBigHeaderBytes);
    if (scene.texture) scene.texture->bind(BALLS_VIEW_SCENE_DEPTH);
    perBall("splat_depth", balls, camera);
  }
  {
    auto scope = profiler.scope("balls.splat.id");
    perBall("splat_id", balls, camera);
  }
  auto scope = profiler.scope("balls.splat.resolve");
  gl::Program& resolve = m_shaders.program({"render/balls/splat_resolve.comp"});
  setCommon(resolve, balls, camera);
  resolve.set("uHasFoam", balls.velocities ? 1 : 0);
  surface.bindImage(BALLS_VIEW_SPLAT_SURFACE, GL_WRITE_ONLY, GL_RGBA32F);
  foam.bindImage(BALLS_VIEW_SPLAT_FOAM, GL_WRITE_ONLY, GL_R16F);
  depth.bindImage(BALLS_VIEW_SPLAT_DEPTH, GL_WRITE_ONLY, GL_R32F);
  resolve.dispatch({unsigned(camera.width + 15) / 16, unsigned(camera.height + 15) / 16, 1u});
  // The blur and compose sample the images; the next frame's kernels read the reset buffers.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace tidepool
