// Depth-aware separable Gaussian blur of the balls' G-buffer for the screen-space water mode:
// two compute passes (rows, then columns; shaders/render/balls/water_blur.comp) that each stage a run
// of texels plus an apron in shared memory. It smooths the depth, normals and thickness of
// neighbouring balls into one surface while depth steps larger than a threshold stay sharp.
#pragma once

#include "gl/shader_library.h"
#include "gl/texture.h"

namespace tidepool {

class WaterBlur {
 public:
  static constexpr int kApron = 16;   // largest kernel radius, px (APRON in the shader)
  static constexpr int kGroup = 256;  // texels a work group stages (GROUP in the shader)

  explicit WaterBlur(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  // source: RGBA32F (or 16F) with A = view depth (m, 0 = empty). pixelRadius: kernel radius in px of
  // a ball at 1 m view depth (it shrinks as 1/depth, capped at kApron); depthThreshold in m.
  // iterations: times the row and column passes run; a second round smooths the streaks one
  // pass leaves where a depth step or silhouette cut its kernel short.
  // perspective false (an orthographic camera): the radius is pixelRadius at every depth.
  void run(const gl::Texture2D& source, float pixelRadius, float depthThreshold, int iterations = 1,
           bool perspective = true);
  const gl::Texture2D& result() const { return m_out; }  // RGBA32F, source's size

 private:
  void pass(int axis, const gl::Texture2D& from, const gl::Texture2D& to, float pixelRadius, float depthThreshold,
            bool perspective);
  gl::ShaderLibrary& m_shaders;
  gl::Texture2D m_rows, m_out;  // after the horizontal pass, after both
};

}  // namespace tidepool
