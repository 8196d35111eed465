#include "render/balls_view.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "render/balls/bindings.glsl"

namespace tidepool {
namespace {
// The tests hold the fragment raster against the compute one (tests/render/balls_golden_test.cpp,
// tests/cli/gpu_limits_test.cpp): TIDEPOOL_BALLS_RASTER=fragment draws with it where the compute
// raster would. Not a scene parameter: the compute raster is the faster wherever it can run.
BallsRaster rasterOf(BallsRaster asked) {
  const char* forced = std::getenv("TIDEPOOL_BALLS_RASTER");
  return forced && std::strcmp(forced, "fragment") == 0 ? BallsRaster::Fragment : asked;
}
}  // namespace

void visit(ParamVisitor& v, BallsViewParams& p) {
  v.choice({"mode", "Mode", "balls: shaded spheres; water: screen-space water surface"}, p.mode, kBallsModeNames);
  v.choice({"debug", "Debug view", "a G-buffer channel instead of the final picture"}, p.debug, kBallsDebugNames);
  v.flag({"debug_unblurred", "Debug before blur",
          "water: the debug views show the G-buffer before the blur (off: the blurred one the water uses)"},
         p.debugUnblurred);
  v.choice({"grid_cells", "Grid cells",
            "the neighbour grid's non-empty cells as wire cubes: by population (blue 1 ball, red full) or all alike"},
           p.gridCells, kGridCellsModeNames);
  v.real({"grid_cells_full", "Grid cells full", "balls per cell drawn red in the population view"}, p.gridCellsFull,
         1.0f, 64.0f);
  const WaterLook look = p.look;
  v.choice({"look", "Look",
            "a preset of the fields below: seed (flat water, dark background), clear (a tiled floor under a sky, "
            "seen through the water), ocean (deeper, greener water there); fields set after it stay"},
           p.look, kWaterLookNames);
  if (p.look != look) applyLook(p, p.look);
  v.flag({"environment", "Environment", "a sky, the sun (towards the light) and a tiled floor (off: the background)"},
         p.environment);
  v.real({"refraction_index", "Refraction index", "water: bends the floor seen through it (1: straight through)"},
         p.refractionIndex, 1.0f, 2.0f);
  v.color({"sky_color", "Sky colour", "linear RGB at the zenith (environment; the horizon is the background)"},
          p.skyColor);
  v.real({"floor_tiles", "Floor tiles", "tiles across the domain box's shorter side (environment)"}, p.floorTiles, 1.0f,
         200.0f);
  v.real(
      {"glass", "Glass", "the box's side walls as glass: their reflectance at normal incidence (environment; 0: none)"},
      p.glass, 0.0f, 1.0f);
  v.real({"caustics", "Caustics",
          "the sunlight the water's surface focuses and spreads on the floor (environment; 0: none, 1: as refracted)"},
         p.caustics, 0.0f, 2.0f);
  v.color({"water_color", "Water colour", "linear RGB: ball albedo, water tint"}, p.waterColor);
  v.real({"absorption", "Absorption", "1/m: this inverse thickness transmits the water colour"}, p.absorption, 0.0f,
         200.0f);
  v.real({"scattering", "Scattering",
          "water: the share of the light it absorbs that it sends back towards the eye, in its colour (0: clear)"},
         p.scattering, 0.0f, 1.0f);
  v.real({"blur_radius", "Blur radius", "water: kernel radius in on-screen ball radii"}, p.blurRadius, 0.0f, 8.0f);
  v.integer({"blur_iterations", "Blur iterations", "water: times the row and column passes run (2: no streaks)"},
            p.blurIterations, 1, 4);
  v.real({"depth_threshold", "Blur depth threshold",
          "water: ball radii of depth step between neighbouring pixels not blurred across"},
         p.depthThreshold, 0.1f, 50.0f);
  v.flag({"foam", "Foam", "white water from each ball's foam"}, p.foam);
  v.real({"spray", "Spray",
          "water: how white a lone ball (a droplet: no more water along the ray than itself) is drawn (0: as water)"},
         p.spray, 0.0f, 1.0f);
  v.real({"fresnel_f0", "Fresnel F0", "water: reflectance at normal incidence"}, p.fresnelF0, 0.0f, 1.0f);
  v.real({"specular", "Specular", "key-light highlight strength"}, p.specular, 0.0f, 4.0f);
  v.vector({"light_direction", "Light direction", "towards the key light, world axes (z up)"}, p.lightDirection, -1.0f,
           1.0f);
  v.color({"obstacle_color", "Obstacle colour", "linear RGB"}, p.obstacleColor);
  v.color({"background", "Background", "linear RGB"}, p.background);
  v.flag({"show_box", "Show box", "domain wireframe"}, p.showBox);
  v.flag({"show_obstacle", "Show obstacle", "draw the obstacle"}, p.showObstacle);
  v.flag({"obstacle_balls", "Obstacle balls", "the obstacle's fixed particles too (they lie up to r outside its mesh)"},
         p.obstacleBalls);
}

namespace {
constexpr float kFloorAlbedo = 0.75f;  // the environment's tiles and grout, on average (environment.glsl)

// The fields a look decides, per look (WaterLook's order).
struct LookFields {
  bool environment;
  float refractionIndex, glass, caustics;
  glm::vec3 skyColor, waterColor;
  float absorption, scattering;
  glm::vec3 background;
  float specular, spray;
};
constexpr BallsViewParams kDefault;  // the clear look
// clang-format off
constexpr std::array<LookFields, 3> kLooks = {{
    // seed: the look tidepool started from, flat blue water (water-webgpu's colour) over a dark
    // background, no environment
    {false, 1.0f, 0.0f, 0.0f, {0.55f, 0.68f, 0.85f}, {0.18f, 0.45f, 0.91f}, 20.0f, 1.0f, {0.09f, 0.10f, 0.12f}, 0.6f, 0.0f},
    // clear (the default): a few centimetres of water nearly clear, a metre of it blue-green; glass's F0 0.04
    {kDefault.environment, kDefault.refractionIndex, kDefault.glass, kDefault.caustics, kDefault.skyColor,
     kDefault.waterColor, kDefault.absorption, kDefault.scattering, kDefault.background, kDefault.specular,
     kDefault.spray},
    // ocean: a few decimetres already deep teal
    {true, 1.33f, 0.04f, 1.0f, {0.22f, 0.40f, 0.72f}, {0.10f, 0.45f, 0.50f}, 12.0f, 0.6f, {0.70f, 0.76f, 0.82f}, 0.8f, 1.0f},
}};
// clang-format on
}  // namespace

void applyLook(BallsViewParams& p, WaterLook look) {
  const LookFields& f = kLooks[std::size_t(look)];
  p.look = look;
  p.environment = f.environment;
  p.refractionIndex = f.refractionIndex;
  p.glass = f.glass;
  p.caustics = f.caustics;
  p.fresnelF0 = kDefault.fresnelF0;  // water's 0.02 in every look
  p.skyColor = f.skyColor;
  p.waterColor = f.waterColor;
  p.absorption = f.absorption;
  p.scattering = f.scattering;
  p.background = f.background;
  p.specular = f.specular;
  p.spray = f.spray;
}

BallsCamera BallsCamera::perspective(glm::mat4 view, float fovYRadians, int width, int height, float near, float far) {
  BallsCamera c;
  c.view = view;
  c.proj = glm::perspective(fovYRadians, float(width) / float(height), near, far);
  c.width = width;
  c.height = height;
  c.near = near;
  c.far = far;
  return c;
}

BallsCamera BallsCamera::orthographic(glm::mat4 view, float halfHeight, int width, int height, float near, float far) {
  const float halfWidth = halfHeight * float(width) / float(height);
  return of(view, glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, near, far), width, height);
}

BallsCamera BallsCamera::of(glm::mat4 view, glm::mat4 proj, int width, int height) {
  BallsCamera c;
  c.view = view;
  c.proj = proj;
  c.width = width;
  c.height = height;
  // Right-handed, z in -1..1. glm::perspective: P[2][2] = -(f+n)/(f-n), P[3][2] = -2fn/(f-n);
  // glm::ortho: P[2][2] = -2/(f-n), P[3][2] = -(f+n)/(f-n).
  if (c.isOrthographic()) {
    c.near = (proj[3][2] + 1.0f) / proj[2][2];
    c.far = (proj[3][2] - 1.0f) / proj[2][2];
  } else {
    c.near = proj[3][2] / (proj[2][2] - 1.0f);
    c.far = proj[3][2] / (proj[2][2] + 1.0f);
  }
  return c;
}

glm::vec3 BallsCamera::towardsLight(glm::vec3 world) const {
  if (glm::dot(world, world) < 1e-12f) world = glm::vec3(0.0f, 0.0f, 1.0f);
  return glm::normalize(glm::vec3(view * glm::vec4(world, 0.0f)));
}

BallsView::BallsView(gl::ShaderLibrary& shaders)
    : m_shaders(shaders),
      m_gbuffer(shaders),
      m_blur(shaders),
      m_caustics(shaders),
      m_compose(shaders),
      m_cells(shaders) {}

const gl::Texture2D& BallsView::composedSurface() const { return m_blurred ? m_blur.result() : m_gbuffer.surface(); }

BallsScene BallsView::sceneOf(const water::ParticleWater& model) {
  // The box turns on screen while gravity stays pointing down (water-webgpu's domain rotation).
  const water::Setup& p = model.water();
  const glm::vec3 centre = 0.5f * (p.domainMin + p.domainMax);
  glm::mat4 world = glm::translate(glm::mat4(1.0f), centre);
  world = glm::rotate(world, -model.domainRotation(), glm::vec3(1, 0, 0));
  world = glm::translate(world, -centre);
  BallsScene s;
  s.water = {&model.positions(), &model.velocities(), model.count(), model.radius(), world};
  const water::Obstacles& obstacles = model.obstacles();
  if (m_params.showObstacle && obstacles.particles() > 0) {
    // Each obstacle's mesh (own frame) where the model placed its particles at the last step.
    m_meshes.update(obstacles, model.radius());
    for (std::size_t k = 0; k < obstacles.size(); ++k)
      if (m_meshes.count(k) > 0)
        s.obstacleMeshes.push_back({&m_meshes.vertices(k), m_meshes.count(k), world * obstacles.pose(k).matrix(),
                                    m_meshes.boundsMin(k), m_meshes.boundsMax(k)});
    s.cover = {&obstacles.placed(), nullptr, obstacles.particles(), model.radius(), world};
    if (m_params.obstacleBalls) s.obstacle = s.cover;
  }
  s.boxMin = model.wallMin();
  s.boxMax = model.wallMax();
  s.boxModel = world;
  return s;
}

void BallsView::render(const water::ParticleWater& model, RenderTarget& target, gl::GpuProfiler& profiler) {
  const water::Setup& p = model.water();
  const glm::vec3 centre = 0.5f * (p.domainMin + p.domainMax);
  m_camera.fit(centre, 0.5f * glm::length(p.domainMax - p.domainMin));
  const BallsCamera camera =
      BallsCamera::of(m_camera.view(), m_camera.projection(float(target.width()) / float(target.height())),
                      target.width(), target.height());
  const BallsScene scene = sceneOf(model);
  render(scene, camera, target, profiler);
  const grid::UniformGrid* grid = model.neighbourGrid();
  if (m_params.gridCells != GridCellsMode::Hidden && grid) {
    auto scope = profiler.scope("balls.grid_cells");
    m_cells.compact(*grid);
    m_cells.draw(*grid, camera.proj * camera.view * scene.boxModel, m_params.gridCells, m_params.gridCellsFull,
                 glm::vec3(1.0f, 0.85f, 0.2f), target);
  }
}

namespace {

WindowRect wholeWindow(const BallsCamera& camera) { return {{0, 0}, {camera.width, camera.height}}; }

}  // namespace

WindowRect meshesWindowRect(const BallsScene& scene, const BallsCamera& camera) {
  const WindowRect whole = wholeWindow(camera);
  if (scene.obstacle.count > 0) return whole;  // the obstacles' balls: no bounds kept for them
  const glm::vec2 size(float(camera.width), float(camera.height));
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const MeshBatch& m : scene.obstacleMeshes) {
    if (m.count == 0) continue;
    if (glm::any(glm::greaterThan(m.boundsMin, m.boundsMax))) return whole;
    const glm::mat4 toView = camera.view * m.model;
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? m.boundsMax.x : m.boundsMin.x, (c & 2) ? m.boundsMax.y : m.boundsMin.y,
                             (c & 4) ? m.boundsMax.z : m.boundsMin.z);
      const glm::vec4 view = toView * glm::vec4(corner, 1.0f);
      if (-view.z <= camera.near) return whole;  // clipped by the near plane, not just projected
      const glm::vec4 clip = camera.proj * view;
      const glm::vec2 px = (0.5f * glm::vec2(clip) / clip.w + 0.5f) * size;
      lo = glm::min(lo, px);
      hi = glm::max(hi, px);
    }
  }
  if (lo.x > hi.x) return {};               // no triangles
  const glm::vec2 far(4.0f * size + 4.0f);  // keeps the float-to-int conversion in range
  WindowRect r{glm::ivec2(glm::floor(glm::clamp(lo, -far, far))) - 1,
               glm::ivec2(glm::ceil(glm::clamp(hi, -far, far))) + 1};
  r.min = glm::clamp(r.min, glm::ivec2(0), whole.max);
  r.max = glm::clamp(r.max, r.min, whole.max);
  return r;
}

WindowRect BallsView::drawScene(const BallsScene& scene, const BallsCamera& camera, RenderTarget& target) {
  const WindowRect rect =
      rasterOf(m_params.raster) == BallsRaster::Compute ? meshesWindowRect(scene, camera) : wholeWindow(camera);
  target.bind();
  // The clear and the draws touch the rectangle only: a depth clear of the whole 1080p target
  // costs 0.15 ms on the H100 (docs/PERFORMANCE.md, "Render"); the later passes treat the rest as far.
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.min.x, rect.min.y, rect.max.x - rect.min.x, rect.max.y - rect.min.y);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  // Depth only: the compose takes the background where the depth is still far, so a colour clear
  // (0.15 ms at 1080p on the H100) would be wasted.
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  m_vao.bind();
  // Both obstacle programs take render/balls/obstacle_light.glsl's colour and key light.
  const auto useWithLight = [&](gl::Program& program) {
    program.use();
    program.set("uColor", m_params.obstacleColor);
    program.set("uLightView", camera.towardsLight(m_params.lightDirection));
    // The environment's sky (its colour at the zenith, brightest channel 1) and floor (its tiles'
    // mean albedo, lit as environment.glsl lights it) as ambient light.
    const glm::vec3 sky =
        m_params.skyColor / std::max({m_params.skyColor.r, m_params.skyColor.g, m_params.skyColor.b, 1e-3f});
    const glm::vec3 sun = m_params.sunWorld();
    const glm::vec3 up = glm::normalize(glm::mat3(camera.view * scene.boxModel) * glm::vec3(0.0f, 0.0f, 1.0f));
    program.set("uSkyLit", m_params.environment ? 1 : 0);
    program.set("uSkyLight", sky);
    program.set("uGroundLight", glm::vec3(kFloorAlbedo * (0.4f + 0.6f * std::max(sun.z, 0.0f))));
    program.set("uUpView", up);
  };
  if (scene.obstacle.count > 0) {
    gl::Program& balls = m_shaders.program({"render/balls/impostor.vert", "render/balls/impostor.frag"});
    useWithLight(balls);
    balls.set("uView", camera.view);
    balls.set("uProj", camera.proj);
    balls.set("uRadius", scene.obstacle.radius);
    balls.set("uModel", scene.obstacle.model);
    balls.set("uHasVelocity", 0);
    scene.obstacle.positions->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_POSITIONS);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * scene.obstacle.count));
  }
  if (!scene.obstacleMeshes.empty()) {
    gl::Program& mesh = m_shaders.program({"render/balls/obstacle_mesh.vert", "render/balls/obstacle_mesh.frag"});
    useWithLight(mesh);
    mesh.set("uProj", camera.proj);
    for (const MeshBatch& batch : scene.obstacleMeshes) {
      mesh.set("uModelView", camera.view * batch.model);
      batch.vertices->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_MESH);
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(batch.count));
    }
  }
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
  return rect;
}

void BallsView::render(const BallsScene& scene, const BallsCamera& camera, RenderTarget& target,
                       gl::GpuProfiler& profiler) {
  const bool water = m_params.mode == BallsMode::Water;
  // The raster runs only for obstacles: without them the compose writes the background itself,
  // and no pass clears the target (raster clears are slow on compute-first GPUs).
  const bool opaque = scene.obstacle.count > 0 || !scene.obstacleMeshes.empty();
  SceneDepth sceneDepth;
  if (opaque) {
    auto scope = profiler.scope("balls.scene");
    sceneDepth = {&target.depth(), drawScene(scene, camera, target)};
  }
  const bool balls = scene.water.count > 0;
  if (balls) {
    const bool thickness = water || m_params.debug == BallsDebug::Thickness;
    m_gbuffer.draw(scene.water, camera, sceneDepth, thickness, rasterOf(m_params.raster), profiler);
  }
  m_blurred = balls && water && m_params.blurRadius > 0.0f;
  if (m_blurred) {
    auto scope = profiler.scope("balls.blur");
    // Kernel radius in px of a ball 1 m away (orthographic: at any depth): scale x r x focal
    // length in px (orthographic: px per m).
    const float focalPx = 0.5f * float(camera.height) * camera.proj[1][1];
    m_blur.run(m_gbuffer.surface(), m_params.blurRadius * scene.water.radius * focalPx,
               m_params.depthThreshold * scene.water.radius, m_params.blurIterations, !camera.isOrthographic());
  }
  const gl::Texture2D* caustics = nullptr;
  if (balls && water && m_params.environment && m_params.caustics > 0.0f) {
    const glm::mat4 boxFromWorld = glm::inverse(scene.boxModel);
    const glm::vec3 sun = m_params.sunWorld();
    const glm::vec3 sunBox = glm::normalize(glm::mat3(boxFromWorld) * sun);
    if (sunBox.z > 0.05f) {  // a sun at the horizon lights the floor by its ambient share only
      auto scope = profiler.scope("balls.caustics");
      m_caustics.run(scene.water, scene.cover, boxFromWorld,
                     {scene.boxMin, scene.boxMax, sunBox, m_params.refractionIndex, m_params.caustics});
      caustics = &m_caustics.light();
    }
  }
  auto scope = profiler.scope("balls.compose");
  const bool raw = m_params.debug != BallsDebug::Final && m_params.debugUnblurred;
  const ComposeScene composed{opaque,         m_params.showBox, scene.boxMin, scene.boxMax,
                              scene.boxModel, sceneDepth.rect,  caustics};
  const gl::Texture2D* surface = nullptr;  // no balls: the compose reads no G-buffer
  if (balls) surface = raw ? &m_gbuffer.surface() : &composedSurface();
  m_compose.draw(surface, m_gbuffer, m_params, camera, scene.water.radius, composed, target);
}

}  // namespace tidepool
