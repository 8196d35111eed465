// Caustics for the water mode's floor: the sunlight the water's surface focuses and spreads on
// the tiled floor of the environment (shaders/render/balls/environment.glsl), as light per floor
// texel (R16F, 1 = dry floor). Three compute passes over a grid of cells on the domain box's
// floor: the water's top per cell from the balls, and the cells the obstacles' balls cover
// (caustics_height.comp, a dispatch for each), that top smoothed
// (caustics_smooth.comp), and the light each floor texel gets through the refracting surface
// above it (caustics_light.comp).
#pragma once

#include "gl/buffer.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/balls_view_params.h"

namespace tidepool {

// Where the caustics are cast: the domain box's floor, in the box's frame (z up).
struct CausticsFloor {
  glm::vec3 min{0.0f}, max{1.0f};   // the box's corners, m: the floor is z = min.z
  glm::vec3 sun{0.0f, 0.0f, 1.0f};  // towards the sun, box frame, unit
  float index = 1.33f;              // the water's index of refraction
  float strength = 1.0f;            // the light written: 1 + strength (light − 1)
};

class WaterCaustics {
 public:
  static constexpr int kMaxCells = 512;          // along the floor's longer side
  static constexpr float kCellPerRadius = 4.0f;  // a cell's edge in ball radii (at most kMaxCells)

  explicit WaterCaustics(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  // The floor's light under the balls of `water`; boxFromBalls maps the world to the box's frame.
  // The floor under the balls of `cover` (the obstacles'; count 0: none) takes no light through
  // the water: it is lit as dry floor, and the water's top stops at its edge.
  void run(const SphereBatch& water, const SphereBatch& cover, const glm::mat4& boxFromWorld,
           const CausticsFloor& floor);
  // The light pass alone, under a given height (R32F, m above the floor, 0 dry) whose texels
  // cover the floor.
  void light(const gl::Texture2D& height, const CausticsFloor& floor);

  const gl::Texture2D& light() const { return m_light; }    // R16F, texels over the floor
  const gl::Texture2D& height() const { return m_height; }  // R32F: the smoothed top, m (0: dry)

 private:
  void resize(glm::ivec2 cells);
  gl::ShaderLibrary& m_shaders;
  gl::Texture2D m_height, m_light;
  gl::Buffer m_tops;  // uint per cell
  glm::ivec2 m_cells{0};
};

}  // namespace tidepool
