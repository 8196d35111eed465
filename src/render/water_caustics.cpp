#include "render/water_caustics.h"

#include <algorithm>
#include <cmath>

#include "gl/kernel.h"
#include "render/balls/bindings.glsl"

namespace tidepool {
namespace {

struct HeightUniforms {  // render/balls/caustics_height.comp
  GLuint count = 0;
  glm::mat4 boxFromBalls{1.0f};
  glm::vec3 floorMin{0.0f};
  glm::vec2 cellSize{1.0f};
  glm::ivec2 cells{0};
  float radius = 0.0f;
  static constexpr auto fields() {
    using U = HeightUniforms;
    return std::tuple{gl::field("uCount", &U::count),       gl::field("uBoxFromBalls", &U::boxFromBalls),
                      gl::field("uFloorMin", &U::floorMin), gl::field("uCellSize", &U::cellSize),
                      gl::field("uCells", &U::cells),       gl::field("uRadius", &U::radius)};
  }
};

struct SmoothUniforms {  // render/balls/caustics_smooth.comp
  glm::ivec2 cells{0};
  GLint height = BALLS_VIEW_CAUSTICS_HEIGHT_IMAGE;  // image unit
  static constexpr auto fields() {
    using U = SmoothUniforms;
    return std::tuple{gl::field("uCells", &U::cells), gl::field("uHeight", &U::height)};
  }
};

struct LightUniforms {  // render/balls/caustics_light.comp
  glm::ivec2 cells{0};
  glm::vec2 cellSize{1.0f};
  glm::vec3 sunBox{0.0f, 0.0f, 1.0f};
  float eta = 1.0f, strength = 1.0f;
  GLint height = BALLS_VIEW_CAUSTICS_HEIGHT, light = BALLS_VIEW_CAUSTICS_LIGHT_IMAGE;  // sampler, image unit
  static constexpr auto fields() {
    using U = LightUniforms;
    return std::tuple{gl::field("uCells", &U::cells),       gl::field("uCellSize", &U::cellSize),
                      gl::field("uSunBox", &U::sunBox),     gl::field("uEta", &U::eta),
                      gl::field("uStrength", &U::strength), gl::field("uHeight", &U::height),
                      gl::field("uLight", &U::light)};
  }
};

glm::uvec3 tiles(glm::ivec2 cells) { return {unsigned(cells.x + 15) / 16, unsigned(cells.y + 15) / 16, 1u}; }

}  // namespace

void WaterCaustics::resize(glm::ivec2 cells) {
  if (cells == m_cells) return;
  m_cells = cells;
  m_height = gl::Texture2D(cells.x, cells.y, GL_R32F);
  m_light = gl::Texture2D(cells.x, cells.y, GL_R16F);
  m_tops = gl::Buffer(std::size_t(cells.x) * std::size_t(cells.y) * sizeof(GLuint));
  m_tops.fillZero();  // the light pass clears it from then on
}

void WaterCaustics::run(const SphereBatch& water, const SphereBatch& cover, const glm::mat4& boxFromWorld,
                        const CausticsFloor& floor) {
  const glm::vec2 extent = glm::vec2(floor.max - floor.min);
  const float cell = std::max(kCellPerRadius * water.radius, std::max(extent.x, extent.y) / float(kMaxCells));
  resize(glm::clamp(glm::ivec2(glm::ceil(extent / cell)), glm::ivec2(1), glm::ivec2(kMaxCells)));
  const glm::vec2 cellSize = extent / glm::vec2(m_cells);
  m_tops.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CAUSTICS_TOPS);
  for (const SphereBatch* batch : {&water, &cover}) {
    if (batch->count == 0) continue;
    const bool covering = batch == &cover;
    const gl::Kernel<HeightUniforms> height(m_shaders, "render/balls/caustics_height.comp",
                                            {BALLS_VIEW_POSITIONS, BALLS_VIEW_CAUSTICS_TOPS},
                                            {{"COVER", covering ? "1" : "0"}});
    batch->positions->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_POSITIONS);
    height.dispatchThreads(batch->count, {.count = GLuint(batch->count),
                                          .boxFromBalls = boxFromWorld * batch->model,
                                          .floorMin = floor.min,
                                          .cellSize = cellSize,
                                          .cells = m_cells,
                                          .radius = batch->radius});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  const gl::Kernel<SmoothUniforms> smooth(m_shaders, "render/balls/caustics_smooth.comp", {BALLS_VIEW_CAUSTICS_TOPS});
  m_height.bindImage(BALLS_VIEW_CAUSTICS_HEIGHT_IMAGE, GL_WRITE_ONLY, GL_R32F);
  smooth.dispatch(tiles(m_cells), {.cells = m_cells});
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  light(m_height, floor);
}

void WaterCaustics::light(const gl::Texture2D& height, const CausticsFloor& floor) {
  resize({height.width(), height.height()});
  const gl::Kernel<LightUniforms> pass(m_shaders, "render/balls/caustics_light.comp", {BALLS_VIEW_CAUSTICS_TOPS});
  height.bind(BALLS_VIEW_CAUSTICS_HEIGHT);
  m_light.bindImage(BALLS_VIEW_CAUSTICS_LIGHT_IMAGE, GL_WRITE_ONLY, GL_R16F);
  m_tops.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CAUSTICS_TOPS);
  pass.dispatch(tiles(m_cells), {.cells = m_cells,
                                 .cellSize = glm::vec2(floor.max - floor.min) / glm::vec2(m_cells),
                                 .sunBox = floor.sun,
                                 .eta = 1.0f / floor.index,
                                 .strength = floor.strength});
  // The compose samples the light; the next frame's height pass writes the cleared tops.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace tidepool
