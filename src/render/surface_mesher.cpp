#include "render/surface_mesher.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "base/error.h"
#include "base/number_text.h"
#include "gl/window.h"
#include "render/marching_cubes.h"
#include "surface/bindings.glsl"

namespace tidepool {
namespace {

constexpr std::size_t kWord = sizeof(std::uint32_t);
// Every kernel's storage blocks (the case table is a uniform block).
constexpr std::initializer_list<GLuint> kSurfaceBindings = {SURFACE_POSITIONS,  SURFACE_DENSITY,  SURFACE_TRI_COUNT,
                                                            SURFACE_VERT_COUNT, SURFACE_VERTICES, SURFACE_NORMALS,
                                                            SURFACE_TRIANGLES};

std::string megabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
  return text;
}

// The grid at `resolution`, without the limit check.
SurfaceGrid layout(const SurfaceInput& in, const SurfaceParams& p, int resolution) {
  SurfaceGrid g;
  g.h = p.smoothing * in.radius;
  const glm::vec3 extent = (in.boxMax - in.boxMin) + 2.0f * g.h;  // where the kernel reaches
  g.cell = std::max({extent.x, extent.y, extent.z}) / float(resolution);
  for (int a = 0; a < 3; ++a)  // the reach, and one cell each side for the shell of zeros
    g.corners[a] = unsigned(std::max(1.0f, std::ceil(extent[a] / g.cell - 1e-4f))) + 3;
  g.origin = in.boxMin - g.h - g.cell;
  // ∫W dV = 64π h³ / 315 for W = (1 - d²/h²)³: one particle per particleVolume sums to 1.
  const double kernelVolume = 64.0 * std::numbers::pi * double(g.h) * g.h * g.h / 315.0;
  g.weightOne = float(SURFACE_FIXED_ONE * double(in.particleVolume) / kernelVolume);
  return g;
}

bool fits(const SurfaceGrid& g, std::size_t maxArrayBytes) {
  const std::size_t n = g.cornerCount();
  return n < grid::PrefixScan::kMaxCount && (n + 1) * kWord <= maxArrayBytes;
}

}  // namespace

SurfaceGrid surfaceGrid(const SurfaceInput& in, const SurfaceParams& p, std::size_t maxArrayBytes) {
  if (p.resolution < 4 || p.resolution > 4096)
    throw Error("--surface-resolution " + std::to_string(p.resolution) +
                " is out of range: 4 to 4096 cells along the longest axis");
  if (!(p.smoothing >= 1.0f && p.smoothing <= 16.0f))
    throw Error("--surface-smoothing " + numberText(p.smoothing) +
                " is out of range: the kernel reaches 1 to 16 particle radii");
  if (!(p.iso > 0.0f && p.iso < 1.0f))
    throw Error("--surface-iso " + numberText(p.iso) + " is out of range: a level between 0 and 1 (water at rest)");
  if (!(in.radius > 0.0f) || !(in.particleVolume > 0.0f) || !glm::all(glm::lessThanEqual(in.boxMin, in.boxMax)))
    throw Error("surface: the particles' radius, volume and box must be positive");
  const SurfaceGrid g = layout(in, p, p.resolution);
  if (fits(g, maxArrayBytes)) return g;
  int best = p.resolution - 1;
  while (best >= 4 && !fits(layout(in, p, best), maxArrayBytes)) --best;
  char line[320];
  std::snprintf(line, sizeof line,
                "--surface-resolution %d needs %ux%ux%u grid corners, %s per array, over this GPU's "
                "GL_MAX_SHADER_STORAGE_BLOCK_SIZE of %s: %s",
                p.resolution, g.corners.x, g.corners.y, g.corners.z,
                megabytes(double(g.cornerCount() + 1) * kWord).c_str(), megabytes(double(maxArrayBytes)).c_str(),
                best >= 4 ? ("at most " + std::to_string(best) + " fits").c_str() : "none fits");
  throw Error(line);
}

SurfaceMesher::SurfaceMesher(gl::ShaderLibrary& shaders)
    : m_ops(shaders),
      m_scan(shaders),
      m_splat(shaders, "surface/splat.comp", kSurfaceBindings),
      m_classify(shaders, "surface/classify.comp", kSurfaceBindings),
      m_emitVertices(shaders, "surface/emit_vertices.comp", kSurfaceBindings),
      m_emitTriangles(shaders, "surface/emit_triangles.comp", kSurfaceBindings),
      m_maxArrayBytes(gl::storageBlockBytes()) {
  const std::vector<glm::uvec4> cases = mc::packedCaseTable();
  m_cases = gl::Buffer(std::span<const glm::uvec4>(cases), GL_STATIC_DRAW);
}

void SurfaceMesher::grow(gl::Buffer& buffer, std::size_t bytes) {
  if (buffer.size() >= bytes && buffer) return;
  // Output arrays get a quarter of headroom (the mesh changes size every frame), up to the limit.
  buffer = gl::Buffer(std::max<std::size_t>(kWord, std::min(bytes + bytes / 4, std::max(bytes, m_maxArrayBytes))));
}

SurfaceMesher::Counts SurfaceMesher::build(const SurfaceInput& in, const SurfaceParams& params,
                                           gl::GpuProfiler* profiler) {
  const auto scope = [profiler](const char* name) {
    return profiler ? profiler->scope(name) : gl::GpuProfiler::Scope(nullptr);
  };
  m_grid = surfaceGrid(in, params, m_maxArrayBytes);
  m_iso = params.iso;
  const std::size_t n = m_grid.cornerCount();
  if (m_density.size() < n * kWord) m_density = gl::Buffer(n * kWord);
  if (m_triStart.size() < (n + 1) * kWord) m_triStart = gl::Buffer((n + 1) * kWord);
  if (m_vertStart.size() < (n + 1) * kWord) m_vertStart = gl::Buffer((n + 1) * kWord);
  {
    auto s = scope("surface.splat");
    m_ops.fill(m_density, 0, n * kWord);
    if (in.count > 0) {
      SplatUniforms u{cube(), 0, m_grid.h / m_grid.cell, 1.0f / (m_grid.h * m_grid.h), m_grid.weightOne};
      m_density.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_DENSITY);
      for (const gl::Window& w : gl::windows(in.count, sizeof(glm::vec4))) {  // positions over one block: windows
        gl::bindWindow(*in.positions, SURFACE_POSITIONS, w, sizeof(glm::vec4));
        u.count = GLuint(w.count);
        m_splat.dispatchThreads(w.count, u);
      }
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
  {
    auto s = scope("surface.classify");
    m_density.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_DENSITY);
    m_triStart.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_TRI_COUNT);
    m_vertStart.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_VERT_COUNT);
    m_cases.bindBase(GL_UNIFORM_BUFFER, SURFACE_CASES);
    m_classify.dispatchThreads(n, cube());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  {
    auto s = scope("surface.scan");
    m_scan.run(m_triStart, m_triStart, n);
    m_scan.run(m_vertStart, m_vertStart, n);
  }
  // The totals (out[n] of each scan), through a small buffer: a read of the big arrays themselves
  // can make the driver move them to memory the CPU reads faster (gl/buffer_ops.h).
  if (m_totals.size() < 2 * kWord) m_totals = gl::Buffer(2 * kWord);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  m_triStart.copyTo(m_totals, kWord, n * kWord, 0);
  m_vertStart.copyTo(m_totals, kWord, n * kWord, kWord);
  const std::vector<std::uint32_t> totals = m_totals.read<std::uint32_t>(2);
  m_counts = {totals[1], totals[0]};
  if (m_counts.vertices * sizeof(glm::vec4) > m_maxArrayBytes || m_counts.triangles * 3 * kWord > m_maxArrayBytes)
    throw Error("surface: " + std::to_string(m_counts.triangles) + " triangles on " +
                std::to_string(m_counts.vertices) + " vertices exceed this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE of " +
                megabytes(double(m_maxArrayBytes)) + ": lower --surface-resolution");
  grow(m_vertices, m_counts.vertices * sizeof(glm::vec4));
  grow(m_normals, m_counts.vertices * sizeof(glm::vec4));
  grow(m_triangles, m_counts.triangles * 3 * kWord);
  {
    auto s = scope("surface.emit");
    // Every binding again: the scan has bound its own buffers over ours.
    m_density.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_DENSITY);
    if (m_counts.vertices > 0) {
      m_vertStart.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_VERT_COUNT);
      m_vertices.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_VERTICES);
      m_normals.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_NORMALS);
      m_emitVertices.dispatchThreads(n, cube());
    }
    if (m_counts.triangles > 0) {
      m_triStart.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_TRI_COUNT);
      m_vertStart.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_VERT_COUNT);
      m_triangles.bindBase(GL_SHADER_STORAGE_BUFFER, SURFACE_TRIANGLES);
      m_cases.bindBase(GL_UNIFORM_BUFFER, SURFACE_CASES);
      m_emitTriangles.dispatchThreads(n, cube());
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  return m_counts;
}

ExportSource SurfaceMesher::exportSource() const {
  const std::size_t v = m_counts.vertices, t = m_counts.triangles;
  ExportSource s;
  if (v > 0) s.ranges = {{&m_vertices, v * sizeof(glm::vec4)}, {&m_normals, v * sizeof(glm::vec4)}};
  if (t > 0) s.ranges.push_back({&m_triangles, t * 3 * kWord});
  s.decode = [v, t](std::span<const std::byte> copied) {
    io::SurfaceFrame frame;
    io::TriangleMesh& mesh = frame.mesh;
    mesh.vertices.resize(v);
    mesh.normals.resize(v);
    mesh.triangles.resize(t);
    for (std::size_t i = 0; i < v; ++i) {
      glm::vec4 p, q;
      std::memcpy(&p, copied.data() + i * sizeof(glm::vec4), sizeof p);
      std::memcpy(&q, copied.data() + (v + i) * sizeof(glm::vec4), sizeof q);
      mesh.vertices[i] = glm::vec3(p);
      mesh.normals[i] = glm::vec3(q);
    }
    if (t > 0) std::memcpy(mesh.triangles.data(), copied.data() + 2 * v * sizeof(glm::vec4), t * sizeof(glm::uvec3));
    return io::ExportFrame(std::move(frame));
  };
  return s;
}

std::size_t SurfaceMesher::memoryBytes() const {
  return m_scan.memoryBytes() + m_cases.size() + m_density.size() + m_triStart.size() + m_vertStart.size() +
         m_vertices.size() + m_normals.size() + m_triangles.size() + m_totals.size();
}

}  // namespace tidepool
