// The water surface as a triangle mesh, built on the GPU from the particles (`--export surface`):
//
//   splat           particles -> density on the corners of a grid (fixed-point atomicAdd)
//   classify        per corner: triangles of its cell (marching-cubes case), vertices it owns
//   scan x 2        both counts -> output offsets (grid/prefix_scan.h, in place)
//   (read back the two totals: the only wait, a few words, to size the outputs)
//   emit vertices   one per crossing edge, numbered by its owner corner: welded by construction
//   emit triangles  each cell's case, as indices of the vertices on its edges
//
// Density: W = (1 - d²/h²)³ for d < h, normalised so that particles at rest (one per
// particleVolume) sum to 1: a block of water reads 1 inside and, by symmetry of the kernel, 0.5
// where its particles' spacing ends (half a spacing beyond the outer centres, where the balls'
// envelope is). Hence the default iso level 0.5. The grid covers the box (the model's domain)
// plus the kernel's reach h, at `resolution` cells along the longest axis, plus one cell each side
// whose outer corners read 0: the mesh is always closed.
//
//   SurfaceMesher mesher(shaders);
//   mesher.build(input, params);                     // throws Error when the grid does not fit
//   exporter.capture(frame, t, mesher.exportSource());
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <string>

#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/gpu_profiler.h"
#include "gl/kernel.h"
#include "grid/prefix_scan.h"
#include "render/export_source.h"

namespace tidepool {

struct SurfaceParams {
  int resolution = 128;    // cells along the longest axis of the box plus the kernel's reach
  float smoothing = 4.0f;  // h, the kernel's reach, in particle radii
  float iso = 0.5f;        // level of the normalised density (1: water at rest)
};

// What the mesher reads of a model (render only reads: nothing here is written).
struct SurfaceInput {
  const gl::Buffer* positions = nullptr;  // vec4 (xyz m, w ignored)
  std::size_t count = 0;                  // particles
  float radius = 0.01f;                   // m, half the spacing at rest
  float particleVolume = 8e-6f;           // m³ per particle at rest: (2r)³ on a cubic lattice
  glm::vec3 boxMin{0.0f}, boxMax{1.0f};   // where the particles are (the domain), m
};

// The grid a build uses: corner (i, j, k) at origin + cell (i, j, k), corners.x fastest.
struct SurfaceGrid {
  glm::vec3 origin{0.0f};
  float cell = 1.0f;       // m
  glm::uvec3 corners{0};   // per axis
  float h = 1.0f;          // kernel reach, m
  float weightOne = 0.0f;  // fixed-point units one particle adds at its own position (W = 1)
  std::size_t cornerCount() const { return std::size_t(corners.x) * corners.y * corners.z; }
};

// The grid for `input` at `params`; throws Error (one line) for a bad parameter or a grid whose
// per-corner arrays exceed `maxArrayBytes` (GL_MAX_SHADER_STORAGE_BLOCK_SIZE), naming that limit
// and the largest resolution that fits.
SurfaceGrid surfaceGrid(const SurfaceInput& input, const SurfaceParams& params, std::size_t maxArrayBytes);

class SurfaceMesher {
 public:
  explicit SurfaceMesher(gl::ShaderLibrary& shaders);

  struct Counts {
    std::size_t vertices = 0, triangles = 0;
  };
  // The mesh of the particles now; scopes "surface.*" in `profiler` when given. Throws Error when
  // the grid or the mesh does not fit the device's limits.
  Counts build(const SurfaceInput& input, const SurfaceParams& params, gl::GpuProfiler* profiler = nullptr);
  // The grid a build of `input` at `params` would use; throws Error as build() does (to refuse
  // before a run starts).
  SurfaceGrid plan(const SurfaceInput& input, const SurfaceParams& params) const {
    return surfaceGrid(input, params, m_maxArrayBytes);
  }
  // The last build's mesh as an export source (render/particle_exporter.h copies it a frame or
  // two before it is written; the next build may start at once).
  ExportSource exportSource() const;

  const Counts& counts() const { return m_counts; }
  const SurfaceGrid& grid() const { return m_grid; }
  const gl::Buffer& density() const { return m_density; }      // uint per corner (fixed point)
  const gl::Buffer& vertices() const { return m_vertices; }    // vec4 per vertex
  const gl::Buffer& normals() const { return m_normals; }      // vec4 per vertex
  const gl::Buffer& triangles() const { return m_triangles; }  // uint x 3 per triangle
  std::size_t memoryBytes() const;                             // every buffer it holds

 private:
  struct CubeUniforms {      // surface/cube.glsl, read by every kernel
    glm::vec3 origin{0.0f};  // corner (0, 0, 0), m
    float cell = 0.0f;       // m
    glm::uvec3 corners{0u};  // per axis
    float iso = 0.5f;        // the surface's level of normalised density
    static constexpr auto fields() {
      using U = CubeUniforms;
      return std::tuple{gl::field("uOrigin", &U::origin), gl::field("uCell", &U::cell),
                        gl::field("uCorners", &U::corners), gl::field("uIso", &U::iso)};
    }
  };
  struct SplatUniforms {
    CubeUniforms cube;
    GLuint count = 0;        // particles
    float reach = 0.0f;      // h / cell
    float invH2 = 0.0f;      // 1 / h², 1/m²
    float weightOne = 0.0f;  // fixed-point units of a kernel peak
    static constexpr auto fields() {
      using U = SplatUniforms;
      return std::tuple{gl::field(&U::cube), gl::field("uCount", &U::count), gl::field("uReach", &U::reach),
                        gl::field("uInvH2", &U::invH2), gl::field("uWeightOne", &U::weightOne)};
    }
  };
  CubeUniforms cube() const { return {m_grid.origin, m_grid.cell, m_grid.corners, m_iso}; }
  void grow(gl::Buffer& buffer, std::size_t bytes);

  gl::BufferOps m_ops;
  grid::PrefixScan m_scan;
  gl::Kernel<SplatUniforms> m_splat;
  gl::Kernel<CubeUniforms> m_classify, m_emitVertices, m_emitTriangles;
  std::size_t m_maxArrayBytes;
  gl::Buffer m_cases;  // uniform block: mc::packedCaseTable()
  gl::Buffer m_density, m_triStart, m_vertStart, m_vertices, m_normals, m_triangles, m_totals;
  SurfaceGrid m_grid;
  float m_iso = 0.5f;
  Counts m_counts;
};

}  // namespace tidepool
