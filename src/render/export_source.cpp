#include "render/export_source.h"

#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <map>
#include <tuple>

#include "render/obstacle_mesh.h"

namespace tidepool {
namespace {

template <class T>
T at(std::span<const std::byte> bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

io::PointField velocityField() { return {"velocity", {"vx", "vy", "vz"}, io::PointType::Float32, {}}; }

// Positions and velocities of particle water (vec4 each: xyz m, w = 1; xyz m/s, w = foam).
io::PointCloud decodeWater(std::span<const std::byte> copied, std::size_t n) {
  io::PointCloud c;
  c.positions.resize(3 * n);
  io::PointField velocity = velocityField(), foam{"foam", {"foam"}, io::PointType::Float32, {}};
  velocity.values.resize(3 * n);
  foam.values.resize(n);
  const std::size_t velAt = n * sizeof(glm::vec4);
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = at<glm::vec4>(copied, i * sizeof(glm::vec4));
    const auto v = at<glm::vec4>(copied, velAt + i * sizeof(glm::vec4));
    for (int k = 0; k < 3; ++k) {
      c.positions[3 * i + k] = p[k];
      velocity.values[3 * i + k] = v[k];
    }
    foam.values[i] = v.w;
  }
  c.fields = {std::move(velocity), std::move(foam)};
  return c;
}

}  // namespace

std::size_t ExportSource::bytes() const {
  std::size_t sum = 0;
  for (const gl::AsyncReadback::Range& r : ranges) sum += r.bytes;
  return sum;
}

ExportSource waterSource(const water::ParticleWater& water) {
  const std::size_t n = water.count(), bytes = n * sizeof(glm::vec4);
  return {{{&water.positions(), bytes}, {&water.velocities(), bytes}},
          [n](std::span<const std::byte> copied) { return io::ExportFrame(decodeWater(copied, n)); }};
}

ExportSource fluidSource(const fluid::Fluid& fluid) {
  ExportSource s = waterSource(fluid);
  const std::size_t n = fluid.count();
  // Before the first step the solver has not measured the density yet: NaN says so in ParaView.
  const float restDensity = fluid.densitiesValid() ? fluid.params().restDensity : NAN;
  s.ranges.push_back({&fluid.densities(), n * sizeof(glm::vec2)});
  s.decode = [n, restDensity](std::span<const std::byte> copied) {
    io::PointCloud c = decodeWater(copied, n);
    io::PointField density{"density", {"density"}, io::PointType::Float32, std::vector<float>(n)};
    const std::size_t densityAt = 2 * n * sizeof(glm::vec4);
    for (std::size_t i = 0; i < n; ++i)
      density.values[i] = restDensity * at<glm::vec2>(copied, densityAt + i * sizeof(glm::vec2)).y;
    c.fields.push_back(std::move(density));
    return io::ExportFrame(std::move(c));
  };
  return s;
}

ExportSource lifeSource(const life::Life& life) {
  const std::size_t n = life.count();
  const bool half = life.storage() == life::Storage::Fp16;
  const std::size_t stride = half ? sizeof(glm::uvec2) : sizeof(glm::vec4);
  return {{{&life.positions(), n * stride}, {&life.velocities(), n * stride}},
          [n, half, stride](std::span<const std::byte> copied) {
            io::PointCloud c;
            c.positions.assign(3 * n, 0.0f);
            io::PointField velocity = velocityField(), species{"species", {"species"}, io::PointType::Int32, {}};
            velocity.values.assign(3 * n, 0.0f);
            species.values.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
              glm::vec2 p, v;
              if (half) {  // (packHalf2x16(xy), species), (packHalf2x16(v), packHalf2x16(a))
                const auto pw = at<glm::uvec2>(copied, i * stride), vw = at<glm::uvec2>(copied, (n + i) * stride);
                p = glm::unpackHalf2x16(pw.x);
                v = glm::unpackHalf2x16(vw.x);
                species.values[i] = float(pw.y);
              } else {  // (x, y, 0, species), (vx, vy, ax, ay)
                const auto pf = at<glm::vec4>(copied, i * stride), vf = at<glm::vec4>(copied, (n + i) * stride);
                p = glm::vec2(pf);
                v = glm::vec2(vf);
                species.values[i] = pf.w;
              }
              c.positions[3 * i] = p.x;
              c.positions[3 * i + 1] = p.y;
              velocity.values[3 * i] = v.x;
              velocity.values[3 * i + 1] = v.y;
            }
            c.fields = {std::move(velocity), std::move(species)};
            return io::ExportFrame(std::move(c));
          }};
}

ExportSource swarmSource(const sim::Swarm& swarm, const gl::Buffer* colors) {
  const std::size_t n = swarm.count(), stride = sim::swarmBytesPerParticle(swarm.storage());
  const bool half = swarm.storage() == sim::Storage::Fp16;
  const float aspect = float(swarm.aspect());
  ExportSource s{{{&swarm.state(), n * stride}}, {}};
  if (colors) s.ranges.push_back({colors, n * sizeof(std::uint32_t)});
  s.decode = [n, stride, half, aspect, colored = colors != nullptr](std::span<const std::byte> copied) {
    io::PointCloud c;
    c.positions.assign(3 * n, 0.0f);
    io::PointField velocity = velocityField(), color{"color", {"red", "green", "blue"}, io::PointType::UInt8, {}};
    velocity.values.assign(3 * n, 0.0f);
    if (colored) color.values.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      glm::vec2 p, v;
      if (half) {
        const auto w = at<glm::uvec2>(copied, i * stride);
        p = glm::unpackHalf2x16(w.x);
        v = glm::unpackHalf2x16(w.y);
      } else {
        const auto f = at<glm::vec4>(copied, i * stride);
        p = glm::vec2(f);
        v = glm::vec2(f.z, f.w);
      }
      c.positions[3 * i] = p.x * aspect;  // NDC -> world units, the velocity's
      c.positions[3 * i + 1] = p.y;
      velocity.values[3 * i] = v.x;
      velocity.values[3 * i + 1] = v.y;
      if (colored) {
        const glm::vec4 rgba = glm::unpackUnorm4x8(at<std::uint32_t>(copied, n * stride + i * 4));
        for (int k = 0; k < 3; ++k) color.values[3 * i + k] = std::round(rgba[k] * 255.0f);
      }
    }
    c.fields.push_back(std::move(velocity));
    if (colored) c.fields.push_back(std::move(color));
    return io::ExportFrame(std::move(c));
  };
  return s;
}

ExportSource ripplesSource(const ripples::Ripples& ripples) {
  const int w = ripples.width(), h = ripples.height();
  const float dx = ripples.params().cellSize;
  const std::size_t n = ripples.count();
  ExportSource s{{{&ripples.state(), n * sizeof(glm::vec2)}}, {}, true};
  s.decode = [w, h, dx, n](std::span<const std::byte> copied) {
    io::HeightField grid{0, w, h, dx, {0.5f * dx, 0.5f * dx}, {}};  // cell centres
    io::PointField height{"height", {"height"}, io::PointType::Float32, std::vector<float>(n)};
    io::PointField velocity{"vertical_velocity", {"vertical_velocity"}, io::PointType::Float32, std::vector<float>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      const auto hv = at<glm::vec2>(copied, i * sizeof(glm::vec2));
      height.values[i] = hv.x;
      velocity.values[i] = hv.y;
    }
    grid.fields = {std::move(height), std::move(velocity)};
    return io::ExportFrame(std::move(grid));
  };
  return s;
}

io::TriangleMesh obstacleSurface(const water::Obstacles& obstacles, float radius) {
  io::TriangleMesh out;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const water::ObstacleBody& body = obstacles.body(k);
    const water::ObstaclePose& pose = obstacles.pose(k);
    const auto first = unsigned(out.vertices.size());
    if (body.mesh) {
      for (const glm::vec3& v : body.mesh->vertices) out.vertices.push_back(pose.place(v));
      for (const glm::uvec3& t : body.mesh->triangles) out.triangles.push_back(t + glm::uvec3(first));
      continue;
    }
    // The surface comes as separate triangles: the same corner is one vertex.
    std::map<std::tuple<float, float, float>, unsigned> index;
    const std::vector<MeshVertex> soup = ballUnionMesh(body.particles, radius);
    for (std::size_t t = 0; t + 2 < soup.size(); t += 3) {
      glm::uvec3 tri;
      for (int c = 0; c < 3; ++c) {
        const glm::vec3 p(soup[t + c].position);
        const auto [it, added] = index.try_emplace({p.x, p.y, p.z}, unsigned(out.vertices.size()));
        if (added) out.vertices.push_back(pose.place(p));
        tri[c] = it->second;
      }
      out.triangles.push_back(tri);
    }
  }
  return out;
}

}  // namespace tidepool
