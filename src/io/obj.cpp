#include "io/obj.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "base/error.h"
#include "io/assets.h"
#include "io/echo.h"
#include "io/json.h"
#include "io/limits.h"
#include "io/output_file.h"

namespace tidepool::io {
namespace {

// Blanks between tokens: spaces, tabs, and the carriage returns, vertical tabs and form feeds
// that old or odd exporters leave mid-line.
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

class Parser {
 public:
  explicit Parser(const std::string& name) : m_name(name) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(m_name + ":" + std::to_string(m_line) + ": " + what);
  }

  float number(std::string_view text, const char* what) const {
    float value = 0;
    const char* first = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
      fail("bad number '" + printable(text) + "' in " + what);
    return value;
  }

  long integer(std::string_view text, const char* what) const {
    long value = 0;
    const char* first = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      fail("bad index '" + printable(text) + "' in " + what);
    return value;
  }

  void vertex(const std::vector<std::string_view>& t) {
    if (t.size() < 4) fail("a vertex needs x y z ('v 0 1 0')");
    if (m_mesh.vertices.size() >= kMaxObjVertices)
      fail("more than " + std::to_string(kMaxObjVertices) + " vertices, the most a mesh may have");
    m_mesh.vertices.emplace_back(number(t[1], "vertex"), number(t[2], "vertex"), number(t[3], "vertex"));
  }

  // One face corner "v", "v/vt", "v/vt/vn" or "v//vn": the position index, 0-based. Texture and
  // normal indices are checked for their form only: a fixed obstacle uses neither.
  unsigned corner(std::string_view text) const {
    std::vector<std::string_view> parts;
    for (std::size_t from = 0;;) {
      const std::size_t slash = text.find('/', from);
      parts.push_back(text.substr(from, slash == std::string_view::npos ? slash : slash - from));
      if (slash == std::string_view::npos) break;
      from = slash + 1;
    }
    if (parts.size() > 3) fail("bad face corner '" + printable(text) + "' (v, v/vt, v/vt/vn or v//vn)");
    for (std::size_t k = 1; k < parts.size(); ++k)
      if (!parts[k].empty()) integer(parts[k], "face");
    const long index = integer(parts[0], "face");
    const long count = long(m_mesh.vertices.size());
    const long resolved = index < 0 ? count + index : index - 1;
    if (index == 0 || resolved < 0 || resolved >= count)
      fail("vertex index " + std::to_string(index) + " out of range (" + std::to_string(count) + " defined so far)");
    return unsigned(resolved);
  }

  void face(const std::vector<std::string_view>& t) {
    if (t.size() < 4) fail("a face needs at least 3 vertices ('f 1 2 3')");
    std::vector<unsigned> v;
    for (std::size_t i = 1; i < t.size(); ++i) v.push_back(corner(t[i]));
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {  // fan from the first corner
      const glm::uvec3 tri(v[0], v[i], v[i + 1]);
      if (tri.x == tri.y || tri.y == tri.z || tri.z == tri.x) continue;
      if (m_mesh.triangles.size() >= kMaxObjTriangles)
        fail("more than " + std::to_string(kMaxObjTriangles) + " triangles, the most a mesh may have");
      m_mesh.triangles.push_back(tri);
    }
  }

  TriangleMesh parse(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      ++m_line;
      std::string_view view(line);
      view = view.substr(0, view.find('#'));
      const std::vector<std::string_view> t = tokens(view);
      if (t.empty()) continue;
      if (t[0] == "v")
        vertex(t);
      else if (t[0] == "f")
        face(t);
      // vt, vn, o, g, s, usemtl, mtllib, l, p...: nothing a fixed obstacle needs
    }
    if (m_mesh.triangles.empty()) throw Error(m_name + ": no triangles (an OBJ mesh needs 'f' lines)");
    return std::move(m_mesh);
  }

 private:
  std::string m_name;
  int m_line = 0;
  TriangleMesh m_mesh;
};

std::string edgeText(glm::uvec2 e) { return std::to_string(e.x) + "-" + std::to_string(e.y); }

}  // namespace

glm::vec3 TriangleMesh::boundsMin() const {
  glm::vec3 lo(std::numeric_limits<float>::max());
  for (const glm::uvec3& t : triangles)
    for (int k = 0; k < 3; ++k) lo = glm::min(lo, vertices[t[k]]);
  return lo;
}

glm::vec3 TriangleMesh::boundsMax() const {
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (const glm::uvec3& t : triangles)
    for (int k = 0; k < 3; ++k) hi = glm::max(hi, vertices[t[k]]);
  return hi;
}

TriangleMesh parseObj(const std::string& text, const std::string& name) {
  if (text.size() > kMaxObjFileBytes)
    throw Error(name + ": " + byteSize(text.size()) + ", larger than the " + byteSize(kMaxObjFileBytes) +
                " allowed for an OBJ mesh");
  return Parser(name).parse(text);
}

TriangleMesh readObj(const std::filesystem::path& path) {
  return parseObj(readFileLimited(path, kMaxObjFileBytes, "an OBJ mesh"), shownPath(path));
}

EdgeCheck checkClosed(const TriangleMesh& mesh) {
  // Weld vertices at equal positions, then count the triangles on each undirected edge.
  auto less = [](const glm::vec3& a, const glm::vec3& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  std::map<glm::vec3, unsigned, decltype(less)> first(less);
  std::vector<unsigned> weld(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    weld[i] = first.emplace(mesh.vertices[i], unsigned(i)).first->second;
  std::map<std::pair<unsigned, unsigned>, int> uses;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const unsigned a = weld[t[k]], b = weld[t[(k + 1) % 3]];
      if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
    }
  EdgeCheck check;
  check.edges = uses.size();
  for (const auto& [edge, n] : uses) {
    if (n == 2) continue;
    if (check.closed()) check.firstBad = glm::uvec2(edge.first + 1, edge.second + 1);
    (n == 1 ? check.boundaryEdges : check.nonManifoldEdges)++;
  }
  return check;
}

std::string EdgeCheck::describe() const {
  if (closed()) return "closed (" + std::to_string(edges) + " edges, each shared by two triangles)";
  std::string s = "not closed:";
  // Appends rather than " " + to_string(): GCC 12 warns (-Wrestrict, a false positive) on the latter.
  if (boundaryEdges > 0)
    s.append(" ").append(std::to_string(boundaryEdges)).append(" edges belong to one triangle only (a hole);");
  if (nonManifoldEdges > 0)
    s.append(" ").append(std::to_string(nonManifoldEdges)).append(" edges are shared by three or more triangles;");
  return s.append(" the first at vertices ").append(edgeText(firstBad));
}

std::filesystem::path findMesh(const std::string& nameOrPath) {
  namespace fs = std::filesystem;
  const fs::path given(nameOrPath);
  std::error_code ec;
  if (nameOrPath.empty()) throw Error("no mesh named: give a file in assets/meshes or a path to an OBJ file");
  if (given.is_absolute() || fs::exists(given, ec)) return given;
  const fs::path dir = findAssetDir() / "meshes";
  for (const fs::path& c : {dir / given, dir / (nameOrPath + ".obj")})
    if (fs::is_regular_file(c, ec)) return c;
  std::vector<std::string> known;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".obj") known.push_back(entry.path().stem().string());
  std::sort(known.begin(), known.end());
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  throw Error("mesh '" + printable(nameOrPath) +
              "' not found: neither a file nor a name in assets/meshes (known: " + list + ")");
}

std::vector<std::uint8_t> objBytes(const TriangleMesh& mesh, const std::string& comment) {
  std::string out;
  out.reserve(40 * mesh.vertices.size() * (mesh.normals.empty() ? 1 : 2) + 40 * mesh.triangles.size() + 64);
  if (!comment.empty()) out += "# " + comment + "\n";
  char line[160];
  for (const glm::vec3& v : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(v.x), double(v.y), double(v.z));
    out += line;
  }
  for (const glm::vec3& n : mesh.normals) {
    std::snprintf(line, sizeof line, "vn %.6g %.6g %.6g\n", double(n.x), double(n.y), double(n.z));
    out += line;
  }
  const bool normals = !mesh.normals.empty();
  for (const glm::uvec3& t : mesh.triangles) {
    const unsigned a = t.x + 1, b = t.y + 1, c = t.z + 1;
    if (normals)
      std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
    else
      std::snprintf(line, sizeof line, "f %u %u %u\n", a, b, c);
    out += line;
  }
  return {out.begin(), out.end()};
}

void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& comment) {
  replaceFile(file, objBytes(mesh, comment));
}

}  // namespace tidepool::io
