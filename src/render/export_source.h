// What the particle export (particle_exporter.h) copies of a model at a frame, and how the copied
// bytes become points with fields (io/point_cloud.h), per model:
//
//   model    buffers copied                     points (m or world units)   fields
//   balls    positions, velocities (vec4)       xyz                         velocity, foam (velocity w)
//   fluid    + densities (vec2 λ, ρ/ρ0)         xyz                         velocity, foam, density (kg/m³)
//   life     positions, velocities (fp32/fp16)  x y 0                       velocity (vx vy 0), species
//   swarm    state (fp32/fp16), colours         world x y 0 (NDC · aspect)  velocity (vx vy 0), color (image mode)
//   ripples  state (vec2 h, v per cell)         a heightfield (cell centres, m)  height, vertical_velocity
//
// The decoder captures by value what it needs of the model now (storage, aspect, rest density),
// because it runs a frame or two later, when the copy has come back.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "gl/async_readback.h"
#include "io/export_series.h"
#include "io/obj.h"
#include "io/point_cloud.h"
#include "sim/fluid/fluid.h"
#include "sim/life/life.h"
#include "sim/ripples/ripples.h"
#include "sim/swarm/swarm.h"
#include "sim/water/obstacles.h"
#include "sim/water/particle_water.h"

namespace tidepool {

struct ExportSource {
  std::vector<gl::AsyncReadback::Range> ranges;  // copied one after the other, in this order
  // The copied bytes (ranges in order) -> points or a heightfield; the exporter sets the time.
  std::function<io::ExportFrame(std::span<const std::byte> copied)> decode;
  bool heightField = false;   // what decode gives (PLY has no form for it)
  std::size_t bytes() const;  // of all ranges
};

ExportSource waterSource(const water::ParticleWater& water);  // balls (and the fluid without its densities)
ExportSource fluidSource(const fluid::Fluid& fluid);
ExportSource lifeSource(const life::Life& life);
// `colors`: the renderer's packUnorm4x8 colour per particle (image colour mode), or null.
ExportSource swarmSource(const sim::Swarm& swarm, const gl::Buffer* colors);
ExportSource ripplesSource(const ripples::Ripples& ripples);

// The obstacles as one triangle mesh where they were placed at the last step: a mesh obstacle's
// file triangles, any other shape the surface around its fixed particles (render/obstacle_mesh.h),
// vertices welded. Empty when there are none.
io::TriangleMesh obstacleSurface(const water::Obstacles& obstacles, float radius);

}  // namespace tidepool
