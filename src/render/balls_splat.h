// Compute rasteriser of the balls' sphere impostors: fills the same G-buffer as the fragment
// path (src/render/balls_gbuffer.h) with the shader cores instead of the raster units, which on
// compute-first GPUs (the H100) draw a million impostors some ten times slower. Three kernels
// (shaders/render/balls/splat_*.comp; the scheme is at the top of render/balls/splat.glsl):
//   depth    per ball: window depth by atomicMin into a uint per pixel; the thickness (when
//            asked) by atomicAdd of fixed-point chords where the ball is in front of the scene
//   id       per ball: where its depth won, its id replaces the depth
//   resolve  per pixel: that ball's hit -> surface (normal xy, thickness, view depth), foam and
//            window depth (R32F here, not a depth attachment); resets the uint buffers
// Balls covering many pixels are drawn by one work group each (an indirect dispatch).
#pragma once

#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/balls_view_params.h"

namespace tidepool {

class BallsSplat {
 public:
  static constexpr float kThicknessSteps = 4096.0f;  // fixed-point units per ball radius
  static constexpr unsigned kMaxBig = 65535;         // balls the big list holds (one group each)

  explicit BallsSplat(gl::ShaderLibrary& shaders);
  // surface RGBA32F, foam R16F and depth R32F of the camera's size receive the frame; thickness
  // is accumulated when `thickness`, in front of the scene's depth (DEPTH32F, same size, inside
  // its rectangle; no texture: nothing opaque).
  void draw(const SphereBatch& balls, const BallsCamera& camera, const SceneDepth& scene, bool thickness,
            const gl::Texture2D& surface, const gl::Texture2D& foam, const gl::Texture2D& depth,
            gl::GpuProfiler& profiler);

 private:
  void resize(const BallsCamera& camera, std::size_t balls);
  void setCommon(gl::Program& program, const SphereBatch& balls, const BallsCamera& camera) const;
  // Runs `kernel` ("splat_depth" or "splat_id" in shaders/render/balls/) over the balls, then its big-ball variant.
  void perBall(const char* kernel, const SphereBatch& balls, const BallsCamera& camera);
  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;
  gl::Buffer m_keys, m_thickness, m_big;  // uint per pixel, uint per pixel, header + list
  unsigned m_bigCapacity = 0;
  bool m_thicknessOn = false;  // this frame's
  bool m_sceneOn = false;      // this frame's: a scene depth to test the thickness against
  WindowRect m_sceneRect;      // and where it holds the meshes
};

}  // namespace tidepool
