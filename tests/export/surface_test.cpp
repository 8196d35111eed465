// The water surface (render/surface_mesher.h) on llvmpipe: the generated marching-cubes table
// closes every case; the GPU mesh equals the CPU reference; a sphere of particles gives a closed,
// consistently oriented mesh of the sphere's volume; a box gives flat faces; an empty frame a
// valid empty file; a grid that does not fit a one-line error naming the limit.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <regex>

#include "reference/surface_reference.h"
#include "render/marching_cubes.h"
#include "render/particle_exporter.h"
#include "support/error_of.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;

namespace {

class SurfaceTest : public test::GlTest {};

// Closed and consistently oriented, by vertex index (the mesh is welded): each directed edge
// appears once and its reverse once. Returns "" or what is wrong.
std::string topologyProblem(const io::TriangleMesh& mesh) {
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, n] : directed) {
    if (n != 1)
      return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) + " runs " + std::to_string(n) +
             " times the same way";
    if (!directed.count({edge.second, edge.first}))
      return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) + " has no reverse (a hole)";
  }
  return "";
}

double volume(const io::TriangleMesh& mesh) {  // divergence theorem: sum of signed tetrahedra
  double v = 0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.vertices[t.x]), b(mesh.vertices[t.y]), c(mesh.vertices[t.z]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

glm::vec3 faceNormal(const io::TriangleMesh& mesh, const glm::uvec3& t) {
  const glm::vec3 a = mesh.vertices[t.x], b = mesh.vertices[t.y], c = mesh.vertices[t.z];
  return glm::cross(b - a, c - a);
}

// Particles on a cubic lattice of spacing 2r: each stands for (2r)³ of water.
SurfaceInput latticeInput(const gl::Buffer& buffer, std::size_t count, float r, glm::vec3 lo, glm::vec3 hi) {
  return {&buffer, count, r, 8.0f * r * r * r, lo, hi};
}

io::TriangleMesh gpuMesh(const SurfaceMesher& m) {
  io::TriangleMesh mesh;
  const auto v = m.counts().vertices, t = m.counts().triangles;
  for (const glm::vec4& p : m.vertices().read<glm::vec4>(v)) mesh.vertices.emplace_back(p);
  for (const glm::vec4& n : m.normals().read<glm::vec4>(v)) mesh.normals.emplace_back(n);
  mesh.triangles = m.triangles().read<glm::uvec3>(t);
  return mesh;
}

}  // namespace

TEST(MarchingCubes, EveryCaseFitsAndTheOneCornerCaseFacesAwayFromIt) {
  for (int bits = 0; bits < 256; ++bits) EXPECT_LE(mc::caseTable()[bits].triangles, mc::kMaxTriangles);
  EXPECT_EQ(mc::caseTable()[0].triangles, 0);
  EXPECT_EQ(mc::caseTable()[255].triangles, 0);
  const mc::Case& one = mc::caseTable()[1];  // corner 0 inside
  ASSERT_EQ(one.triangles, 1);
  glm::vec3 p[3];
  for (int k = 0; k < 3; ++k) {
    const int e = one.edges[k];
    p[k] = glm::vec3(mc::edgeStart(e));
    p[k][mc::edgeAxis(e)] += 0.5f;
  }
  EXPECT_GT(glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), glm::vec3(1.0f)), 0.0f);  // away from (0, 0, 0)
  EXPECT_EQ(mc::edgeCorner(0, 0), 0);
  EXPECT_EQ(mc::edgeCorner(0, 1), 1);
  EXPECT_EQ(mc::edgeCorner(11, 1), 7);
}

// Random densities hit every kind of case, the ambiguous faces included: still closed and oriented.
TEST(MarchingCubes, RandomFieldsGiveClosedOrientedMeshes) {
  SurfaceGrid g;
  g.corners = glm::uvec3(18, 17, 16);
  g.cell = 0.1f;
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> value(0, 65536);
  std::vector<std::uint32_t> density(g.cornerCount());
  for (auto& d : density) d = value(rng);
  const io::TriangleMesh mesh = marchReference(density, g, 0.5f);
  EXPECT_GT(mesh.triangles.size(), 3000u);
  EXPECT_EQ(topologyProblem(mesh), "");
}

TEST_F(SurfaceTest, GpuMatchesTheCpuReference) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.1f, 0.9f);
  std::vector<glm::vec4> particles(300);
  for (auto& p : particles) p = glm::vec4(u(rng), u(rng), 0.5f * u(rng), 1.0f);
  particles[7] = glm::vec4(3e30f, -3e30f, 1e20f, 1.0f);  // flung far away: adds nothing, ends
  particles[8] = glm::vec4(NAN, 0.5f, 0.5f, 1.0f);
  const gl::Buffer buffer{std::span<const glm::vec4>(particles)};
  const SurfaceInput input{&buffer, particles.size(), 0.03f, 2e-4f, {0, 0, 0}, {1, 1, 0.5f}};
  const SurfaceParams params{14, 2.0f, 0.5f};
  SurfaceMesher mesher(shaders());
  const SurfaceMesher::Counts counts = mesher.build(input, params);
  // The splat: the same fixed-point sums (a float rounding may move a weight by one unit).
  const std::vector<std::uint32_t> density = mesher.density().read<std::uint32_t>(mesher.grid().cornerCount());
  const std::vector<std::uint32_t> reference = splatReference(particles, mesher.grid());
  std::size_t nonZero = 0;
  for (std::size_t i = 0; i < density.size(); ++i) {
    EXPECT_NEAR(double(density[i]), double(reference[i]), 4.0) << "corner " << i;
    nonZero += density[i] > 0;
  }
  EXPECT_GT(nonZero, density.size() / 20);
  // Marching cubes on the GPU's own density: the same mesh.
  const io::TriangleMesh cpu = marchReference(density, mesher.grid(), params.iso);
  const io::TriangleMesh gpu = gpuMesh(mesher);
  ASSERT_EQ(counts.vertices, cpu.vertices.size());
  ASSERT_EQ(counts.triangles, cpu.triangles.size());
  EXPECT_GT(counts.triangles, 100u);
  EXPECT_EQ(gpu.triangles, cpu.triangles);
  for (std::size_t i = 0; i < cpu.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(gpu.vertices[i][k], cpu.vertices[i][k], 1e-5) << "vertex " << i;
      ASSERT_NEAR(gpu.normals[i][k], cpu.normals[i][k], 1e-4) << "normal " << i;
    }
  }
  EXPECT_EQ(topologyProblem(gpu), "");
}

// A ball of water: lattice points within R, each standing for (2r)³, fill (4/3)πR³.
TEST_F(SurfaceTest, SphereIsClosedOrientedOutwardAndHoldsItsVolume) {
  const float r = 0.01f, radius = 0.2f, d = 2 * r;
  std::vector<glm::vec4> particles;
  const int n = int(radius / d) + 1;
  for (int z = -n; z <= n; ++z)
    for (int y = -n; y <= n; ++y)
      for (int x = -n; x <= n; ++x)
        if (glm::length(glm::vec3(x, y, z) * d) <= radius) particles.emplace_back(glm::vec3(x, y, z) * d, 1.0f);
  const gl::Buffer buffer{std::span<const glm::vec4>(particles)};
  SurfaceMesher mesher(shaders());
  mesher.build(latticeInput(buffer, particles.size(), r, glm::vec3(-radius), glm::vec3(radius)), {48, 4.0f, 0.5f});
  const io::TriangleMesh mesh = gpuMesh(mesher);
  ASSERT_GT(mesh.triangles.size(), 1000u);
  EXPECT_EQ(topologyProblem(mesh), "");
  const double expected = 4.0 / 3.0 * std::numbers::pi * std::pow(double(radius), 3);
  std::printf("sphere: %zu particles, %zu triangles, volume %.4f of (4/3)πR³\n", particles.size(),
              mesh.triangles.size(), volume(mesh) / expected);
  EXPECT_NEAR(volume(mesh) / expected, 1.0, 0.03) << "volume " << volume(mesh) << " m³, sphere " << expected;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    ASSERT_GT(glm::dot(mesh.normals[i], glm::normalize(mesh.vertices[i])), 0.9f) << "vertex " << i;
  for (const glm::uvec3& t : mesh.triangles)  // the winding agrees with the normals
    ASSERT_GT(glm::dot(faceNormal(mesh, t), mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z]), 0.0f);
}

// A block of water: away from its edges each side is flat, facing along its axis, where the
// particles' spacing ends (half a spacing beyond the outer centres).
TEST_F(SurfaceTest, BoxHasFlatFacesWhereTheWaterEnds) {
  const float r = 0.01f, d = 2 * r;
  const glm::ivec3 n(16, 12, 10);
  std::vector<glm::vec4> particles;
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) particles.emplace_back((glm::vec3(x, y, z) + 0.5f) * d, 1.0f);
  const glm::vec3 size = glm::vec3(n) * d;  // the water: [0, size]
  const gl::Buffer buffer{std::span<const glm::vec4>(particles)};
  SurfaceMesher mesher(shaders());
  mesher.build(latticeInput(buffer, particles.size(), r, glm::vec3(0), size), {40, 4.0f, 0.5f});
  const io::TriangleMesh mesh = gpuMesh(mesher);
  EXPECT_EQ(topologyProblem(mesh), "");
  const float margin = 4 * r + mesher.grid().cell;  // the kernel's reach and a cell from the edges
  int faces[6] = {};
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 c = (mesh.vertices[t.x] + mesh.vertices[t.y] + mesh.vertices[t.z]) / 3.0f;
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (c[u] < margin || c[u] > size[u] - margin || c[v] < margin || c[v] > size[v] - margin) continue;
      const int side = c[axis] > 0.5f * size[axis] ? 1 : 0;
      glm::vec3 outward(0.0f);
      outward[axis] = side ? 1.0f : -1.0f;
      const glm::vec3 normal = glm::normalize(faceNormal(mesh, t));
      EXPECT_GT(glm::dot(normal, outward), std::cos(glm::radians(3.0f))) << "axis " << axis << " side " << side;
      EXPECT_NEAR(c[axis], side ? size[axis] : 0.0f, 0.25f * d) << "axis " << axis << " side " << side;
      ++faces[2 * axis + side];
    }
  }
  for (int f = 0; f < 6; ++f) EXPECT_GT(faces[f], 10) << "face " << f;
}

TEST_F(SurfaceTest, AnEmptyFrameWritesAValidEmptyPly) {
  const gl::Buffer buffer(16);
  SurfaceMesher mesher(shaders());
  const SurfaceMesher::Counts counts = mesher.build({&buffer, 0, 0.01f, 8e-6f, {0, 0, 0}, {1, 1, 1}}, {});
  EXPECT_EQ(counts.vertices, 0u);
  EXPECT_EQ(counts.triangles, 0u);
  test::TempDir dir;
  ParticleExporter exporter(dir.path(), io::ExportFormat::Ply, 1);
  exporter.capture(0, 0.25, mesher.exportSource());
  exporter.finish();
  std::ifstream in(dir / "surface_00000.ply", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes,
            "ply\nformat binary_little_endian 1.0\ncomment tidepool time 0.25\nelement vertex 0\nproperty float x\n"
            "property float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
            "element face 0\nproperty list uchar int vertex_indices\nend_header\n");
}

TEST(SurfaceGrid, BadParametersAndGridsOverTheLimitAreOneLine) {
  const SurfaceInput input{nullptr, 0, 0.01f, 8e-6f, {0, 0, 0}, {2, 1, 1}};
  const std::string low = test::errorOf([&] { surfaceGrid(input, {3, 4.0f, 0.5f}, SIZE_MAX); });
  EXPECT_EQ(low, "--surface-resolution 3 is out of range: 4 to 4096 cells along the longest axis");
  const std::string big = test::errorOf([&] { surfaceGrid(input, {512, 4.0f, 0.5f}, std::size_t(16) << 20); });
  EXPECT_NE(big.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE of 16.8 MB: at most "), std::string::npos) << big;
  EXPECT_EQ(big.find('\n'), std::string::npos) << big;
  EXPECT_NE(test::errorOf([&] {
              surfaceGrid(input, {64, 0.5f, 0.5f}, SIZE_MAX);
            }).find("--surface-smoothing"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] {
              surfaceGrid(input, {64, 4.0f, 1.5f}, SIZE_MAX);
            }).find("--surface-iso"),
            std::string::npos);
  const SurfaceGrid g = surfaceGrid(input, {100, 4.0f, 0.5f}, SIZE_MAX);
  EXPECT_NEAR(g.cell, (2.0f + 0.08f) / 100.0f, 1e-6f);
  EXPECT_EQ(g.corners.x, 103u);  // 100 cells, one more each side, + 1 for corners
}

// `tidepool render --export surface` end to end: one file per exported frame in the format asked
// for, a one-line refusal for a model without water, a resolution out of range or over the
// device's limit, and surface options without --export surface.
TEST(SurfaceCli, WritesOneMeshPerExportedFrameAndRefusesWhatItCannot) {
  const std::string balls = std::string(TIDEPOOL_TEST_DATA) + "/soak/balls.json";
  test::TempDir dir;
  const test::ProcessResult r =
      test::runTidepool({"render", balls, "--frames", "3", "--size", "32x18", "--export", "surface", "--every", "2",
                         "--surface-resolution", "24", "--surface-format", "obj", "--no-frames", "--quiet", "--out",
                         (dir / "obj").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "obj/surface_00000.obj"));
  EXPECT_TRUE(std::filesystem::exists(dir / "obj/surface_00002.obj"));
  EXPECT_FALSE(std::filesystem::exists(dir / "obj/surface_00001.obj"));
  const io::TriangleMesh mesh = io::readObj(dir / "obj/surface_00002.obj");
  EXPECT_GT(mesh.triangles.size(), 20u);
  EXPECT_TRUE(io::checkClosed(mesh).closed()) << io::checkClosed(mesh).describe();

  const std::string out = (dir / "out").string();
  test::expectOneLineError({"render", "life", "--frames", "2", "--export", "surface", "--out", out, "--quiet"},
                           "life has no water: --export surface needs a balls or fluid scene");
  test::expectOneLineError(
      {"render", balls, "--frames", "2", "--export", "surface", "--surface-resolution", "2", "--out", out, "--quiet"},
      "--surface-resolution 2 is out of range: 4 to 4096 cells along the longest axis");
  test::expectOneLineError({"render", balls, "--frames", "2", "--export", "surface", "--surface-resolution", "4096",
                            "--out", out, "--quiet"},
                           "over this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE");
  test::expectOneLineError(
      {"render", balls, "--frames", "2", "--export", "ply", "--surface-iso", "0.4", "--out", out, "--quiet"},
      "--surface-iso needs --export surface");
  test::expectOneLineError(
      {"render", balls, "--frames", "2", "--export", "surface", "--surface-format", "stl", "--out", out, "--quiet"},
      "--surface-format 'stl' is not a format (expected ply, obj or vtk)");
}

TEST(SurfaceCli, BenchPrintsARowPerResolution) {
  const std::string balls = std::string(TIDEPOOL_TEST_DATA) + "/soak/balls.json";
  const test::ProcessResult r = test::runTidepool(
      {"bench", "surface", balls, "--resolution", "16,24", "--repeats", "1", "--warmup", "0", "--steps", "1"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* row : {R"(\n +[0-9]+ +16 +[0-9]+x[0-9]+x[0-9]+ +[1-9])", R"(\n +[0-9]+ +24 +[0-9]+x)"})
    EXPECT_TRUE(std::regex_search(r.out, std::regex(row))) << row << "\n" << r.out;
  test::expectOneLineError({"bench", "surface", "life", "--repeats", "1"}, "life has no water");
  test::expectOneLineError({"bench", "surface", "life", "--particles", "1000"},
                           "--particles needs a balls or fluid scene");
}
