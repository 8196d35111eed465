#include "sim/water/obstacles.h"

#include <algorithm>

#include "balls/bindings.glsl"
#include "base/error.h"
#include "sim/water/water_init.h"

namespace tidepool::water {
namespace {

struct PlaceUniforms {
  GLuint count = 0;  // obstacle particles
  static constexpr auto fields() { return std::tuple{gl::field("uCount", &PlaceUniforms::count)}; }
};

static_assert(kMaxObstacles == BALLS_MAX_OBSTACLES, "the pose block holds BALLS_MAX_OBSTACLES obstacles");

// The uniform block of shaders/balls/obstacle_poses.glsl (std140: every array element a vec4).
struct PoseBlock {
  glm::vec4 rotation[3 * kMaxObstacles];  // columns of each obstacle's rotation
  glm::vec4 centre[kMaxObstacles];
  glm::vec4 velocity[kMaxObstacles];
  glm::vec4 omega[kMaxObstacles];
  glm::uvec4 particles[kMaxObstacles];  // the first of its particles, how many
};

// The parameters a body is built from, from `from` (the pose stays as it is).
void copyBody(ObstacleParams& to, const ObstacleParams& from) {
  to.shape = from.shape;
  to.mesh = from.mesh;
  to.shell = from.shell;
  to.size = from.size;
}

std::string at(std::size_t k) { return "obstacles[" + std::to_string(k) + "]"; }

// The kernels read the obstacles' particles and their grid through buffer textures
// (common/obstacle_grid.glsl): what passes the limit, or empty.
std::string overTexelLimit(std::size_t texels, const std::string& what, const char* remedy) {
  if (texels <= gl::BufferTexture::maxTexels()) return {};
  return what + ", over this GPU's buffer-texture limit of " + std::to_string(gl::BufferTexture::maxTexels()) +
         ": make " + remedy + " smaller or the radius larger";
}

std::string tooManyParticles(const std::vector<ObstacleBody>& bodies) {
  std::size_t total = 0;
  for (const ObstacleBody& b : bodies) total += b.particles.size();
  return overTexelLimit(total, std::to_string(total) + " fixed particles", "the obstacles");
}

}  // namespace

ObstacleBody Obstacles::buildOne(const ObstacleParams& o, float radius) {
  auto shape = std::make_shared<const Obstacle>(o, radius);
  ObstacleBody b;
  b.built = o;
  b.particles = shape->particles();
  if (shape->mesh()) b.mesh = std::make_shared<const io::TriangleMesh>(*shape->mesh());
  b.shape = std::move(shape);
  for (const glm::vec4& q : b.particles) b.reach = std::max(b.reach, glm::length(glm::vec3(q)));
  b.reach += radius;
  b.id = m_nextId++;
  return b;
}

void Obstacles::build(const std::vector<ObstacleParams>& params, float radius) {
  if (params.size() > kMaxObstacles)
    throw Error(std::to_string(params.size()) + " obstacles, at most " + std::to_string(kMaxObstacles));
  std::vector<ObstacleBody> bodies;
  for (std::size_t k = 0; k < params.size(); ++k) try {
      bodies.push_back(buildOne(params[k], radius));
    } catch (const Error& e) {
      throw Error(at(k) + ": " + e.what());
    }
  if (const std::string over = tooManyParticles(bodies); !over.empty()) throw Error("obstacles: " + over);
  m_bodies = std::move(bodies);
  m_radius = radius;
  upload();
}

bool Obstacles::update(std::vector<ObstacleParams>& params, float radius, std::string& error) {
  if (params.size() > kMaxObstacles) params.resize(kMaxObstacles);
  bool changed = params.size() != m_bodies.size();
  std::vector<ObstacleBody> next;
  std::vector<bool> used(m_bodies.size(), false);
  for (std::size_t k = 0; k < params.size();) {
    // The body built before for these parameters: at the same index, or (after a removal) another.
    std::size_t j = k < m_bodies.size() && sameBody(m_bodies[k].built, params[k]) ? k : m_bodies.size();
    for (std::size_t i = 0; j == m_bodies.size() && i < m_bodies.size(); ++i)
      if (!used[i] && sameBody(m_bodies[i].built, params[k])) j = i;
    if (j < m_bodies.size() && !used[j]) {
      used[j] = true;
      changed |= j != k;
      next.push_back(m_bodies[j]);
      next.back().built = params[k];
      ++k;
      continue;
    }
    changed = true;
    try {
      next.push_back(buildOne(params[k], radius));
      ++k;
    } catch (const Error& e) {
      error = at(k) + " not changed: " + e.what();
      if (k < m_bodies.size() && !used[k]) {  // it was edited: back to what it was
        used[k] = true;
        copyBody(params[k], m_bodies[k].built);
        next.push_back(m_bodies[k]);
        ++k;
      } else {  // it was added: dropped
        params.erase(params.begin() + std::ptrdiff_t(k));
      }
    }
  }
  if (!changed) return false;
  if (const std::string over = tooManyParticles(next); !over.empty()) {  // the whole edit refused
    error = "obstacles not changed: " + over;
    params.resize(m_bodies.size());
    for (std::size_t k = 0; k < m_bodies.size(); ++k) params[k] = m_bodies[k].built;
    return true;
  }
  m_bodies = std::move(next);
  upload();
  return true;
}

void Obstacles::upload() {
  std::vector<glm::vec4> all;
  for (std::size_t k = 0; k < m_bodies.size(); ++k) {
    m_bodies[k].first = all.size();
    for (const glm::vec4& q : m_bodies[k].particles) all.emplace_back(glm::vec3(q), float(k));
  }
  m_particles = all.size();
  m_poses.assign(m_bodies.size(), ObstaclePose{});
  m_dirty = true;
  m_grid.reset();  // place() makes one for the new count
  if (all.empty()) return;
  const std::size_t bytes = all.size() * sizeof(glm::vec4);
  m_body = gl::Buffer(bytes, all.data());
  m_world = gl::Buffer(bytes);
  m_sorted = gl::Buffer(bytes);
  if (m_volumeFn) {
    m_volumeSorted = gl::Buffer(bytes);
    refreshVolumes();
  }
}

void Obstacles::refreshVolumes() {
  if (!m_volumeFn || m_particles == 0) return;
  std::vector<glm::vec4> all;
  for (const ObstacleBody& b : m_bodies)
    for (float v : m_volumeFn(b)) all.emplace_back(v, 0.0f, 0.0f, 0.0f);
  m_volumeBody = gl::Buffer(all.size() * sizeof(glm::vec4), all.data());
  m_dirty = true;  // sorted again at the next place()
}

void Obstacles::place(const std::vector<ObstacleParams>& params, std::vector<ObstaclePose> poses, glm::vec3 domainMin,
                      glm::vec3 domainMax, gl::GpuProfiler* profiler) {
  poses.resize(m_bodies.size());
  const bool moved = m_dirty || poses != m_poses;
  m_poses = std::move(poses);
  m_dirty = false;
  if (!moved || m_particles == 0) return;

  PoseBlock block{};
  for (std::size_t k = 0; k < m_poses.size(); ++k) {
    const ObstaclePose& q = m_poses[k];
    for (int c = 0; c < 3; ++c) block.rotation[3 * k + std::size_t(c)] = glm::vec4(q.rotation[c], 0.0f);
    block.centre[k] = glm::vec4(q.centre, 0.0f);
    block.velocity[k] = glm::vec4(q.velocity, 0.0f);
    block.omega[k] = glm::vec4(q.omega, 0.0f);
    block.particles[k] = glm::uvec4(m_bodies[k].first, m_bodies[k].particles.size(), 0u, 0u);
  }
  if (!m_poseBlock) m_poseBlock = gl::Buffer(sizeof block, nullptr, GL_DYNAMIC_DRAW);
  m_poseBlock.upload(&block, sizeof block);

  // The grid covers where the obstacles can be (each one's reach about its path's range of
  // centres, fixed while it moves; a body's about where it is) and balls can touch them (the
  // domain and 2r around it).
  const float margin = 2.0f * m_radius;
  glm::vec3 lo(1e30f), hi(-1e30f);
  bool dynamic = false;
  for (std::size_t k = 0; k < m_bodies.size(); ++k) {
    if (m_bodies[k].particles.empty()) continue;
    const ObstacleParams& o = params[k];
    if (o.dynamic) {  // where it is now
      lo = glm::min(lo, m_poses[k].centre - m_bodies[k].reach);
      hi = glm::max(hi, m_poses[k].centre + m_bodies[k].reach);
      dynamic = true;
      continue;
    }
    const glm::vec3 swing = o.path.kind == PathKind::None ? glm::vec3(0.0f) : glm::abs(o.path.amplitude);
    lo = glm::min(lo, o.centre - swing - m_bodies[k].reach);
    hi = glm::max(hi, o.centre + swing + m_bodies[k].reach);
  }
  if (dynamic) {
    // Bodies move every step: their bounds in whole blocks of 16 cells, so that the grid is made
    // anew only when one crosses into another block. Water particles outside the grid skip the
    // obstacles at once, so it covers no more of the domain than the bodies need.
    const float block = 16.0f * cellSize();
    lo = domainMin + glm::floor((lo - domainMin) / block) * block;
    hi = domainMin + glm::ceil((hi - domainMin) / block) * block;
  }
  lo = glm::max(lo - margin, domainMin - margin);
  hi = glm::min(hi + margin, domainMax + margin);
  hi = glm::max(hi, lo + margin);  // all outside the domain: a token grid
  if (!m_grid || m_grid->params().domainMin != lo || m_grid->params().domainMax != hi) {
    auto grid = std::make_unique<grid::UniformGrid>(m_shaders, grid::GridParams{lo, hi, 2.0f * m_radius}, m_particles);
    const std::string cells = "a grid of " + std::to_string(grid->cells()) + " cells around them";
    if (const std::string over = overTexelLimit(grid->cells() + 1, cells, "them"); !over.empty())
      throw Error("obstacles: " + over);
    m_grid = std::move(grid);
  }

  auto scope = profiler ? profiler->scope("balls.obstacles") : gl::GpuProfiler::Scope(nullptr);
  const gl::Kernel<PlaceUniforms> place(m_shaders, "balls/obstacle_place.comp", {BALLS_POS_IN, BALLS_POS_OUT});
  m_poseBlock.bindBase(GL_UNIFORM_BUFFER, BALLS_OBST_POSES);
  m_body.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
  m_world.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_OUT);
  place.dispatchThreads(m_particles, {GLuint(m_particles)});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  m_grid->build(m_world, m_particles);
  if (m_volumeFn)
    m_grid->reorder(m_world, {{&m_world, &m_sorted}, {&m_volumeBody, &m_volumeSorted}});
  else
    m_grid->reorder(m_world, {{&m_world, &m_sorted}});
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the kernels read them through buffer textures
}

bool Obstacles::occupied(glm::vec3 world) const {
  for (std::size_t k = 0; k < m_bodies.size(); ++k) {
    const glm::vec3 q = m_poses[k].toBody(world);
    if (glm::length(q) <= m_bodies[k].reach && m_bodies[k].shape->inside(q)) return true;
  }
  return false;
}

ObstacleUniforms Obstacles::uniforms() const {
  if (!m_grid) return {};
  const grid::GridParams& g = m_grid->params();
  return {.origin = g.domainMin, .invCell = 1.0f / g.cellSize, .dims = m_grid->dims()};
}

void Obstacles::bind() const {
  if (!m_grid) return;
  m_poseBlock.bindBase(GL_UNIFORM_BUFFER, BALLS_OBST_POSES);
  m_textures[0].bind(OBSTACLE_POS_UNIT, m_sorted.id(), GL_RGBA32F);
  m_textures[1].bind(OBSTACLE_CELL_START_UNIT, m_grid->cellStart().id(), GL_R32UI);
  if (m_volumeFn) m_textures[2].bind(OBSTACLE_VOLUME_UNIT, m_volumeSorted.id(), GL_RGBA32F);
}

}  // namespace tidepool::water
