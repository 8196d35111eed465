#version 430 core
// Caustics, second pass: the water's height over each floor cell, smoothed: the mean of the tops
// (caustics_height.comp) in the 5 x 5 cells about it that hold water, weighted by a binomial
// kernel, so that the balls' bumps do not scatter the light as ripples would. A cell is wet when
// the cells holding water carry at least half the kernel's weight there (a cell no ball's centre
// fell in, inside the water, is filled; one outside its edge stays dry, 0; so does a cell an
// obstacle covers, and covered cells count as dry in the mean). caustics_light.comp
// clears the tops afterwards, for the next frame.
#include "render/balls/bindings.glsl"
#include "render/balls/caustics_cells.glsl"
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = BALLS_VIEW_CAUSTICS_TOPS) readonly buffer Tops { uint tops[]; };
layout(binding = BALLS_VIEW_CAUSTICS_HEIGHT_IMAGE, r32f) writeonly uniform image2D uHeight;
uniform ivec2 uCells;

void main() {
  const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(cell, uCells))) return;
  const float weights[5] = float[5](1.0, 4.0, 6.0, 4.0, 1.0);
  float sum = 0.0, wet = 0.0, around = 0.0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const ivec2 q = cell + ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, uCells))) continue;
      const float w = weights[dx + 2] * weights[dy + 2];
      around += w;
      const uint top = tops[q.y * uCells.x + q.x];
      if (top == 0u || top == kCovered) continue;
      sum += w * uintBitsToFloat(top);
      wet += w;
    }
  const bool covered = tops[cell.y * uCells.x + cell.x] == kCovered;
  imageStore(uHeight, cell, vec4(wet >= 0.5 * around && !covered ? sum / wet : 0.0, 0.0, 0.0, 0.0));
}
