#version 430 core
// Grid cells view: one instance per non-empty cell of the compacted list (glDrawArraysIndirect,
// balls_grid_cells.h), 24 vertices from gl_VertexID drawing its cube's 12 edges as GL_LINES.
// Colour: a ramp over the cell's population (uByPopulation 1) or one colour for all.
#include "render/balls/bindings.glsl"

layout(std430, binding = BALLS_VIEW_CELL_COUNT) readonly buffer Counts { uint cellCount[]; };
layout(std430, binding = BALLS_VIEW_CELL_LIST) readonly buffer List {
  uint drawHeader[4];  // the indirect command
  uint cellIds[];
};

uniform mat4 uClipFromGrid;  // the grid's frame (the simulation's) -> clip
uniform vec3 uOrigin;        // grid domain min (m)
uniform float uCellSize;     // m
uniform uvec3 uDims;         // cells per axis
uniform int uByPopulation;   // 1: colour by count, 0: uColor
uniform float uFullCount;    // balls per cell at the ramp's top
uniform vec3 uColor;         // linear RGB

out vec3 vColor;

// Edge k joins corner a and corner a | bit (corner bits: x 1, y 2, z 4), as boxEdgesInWindow.
const ivec2 kEdges[12] = ivec2[](ivec2(0, 1), ivec2(2, 3), ivec2(4, 5), ivec2(6, 7), ivec2(0, 2), ivec2(1, 3),
                                 ivec2(4, 6), ivec2(5, 7), ivec2(0, 4), ivec2(1, 5), ivec2(2, 6), ivec2(3, 7));

// Jet: dark blue, blue, cyan, yellow, red over t in [0, 1]; the cells take it from 0.2 (a light
// blue for one ball) to 1 (red for uFullCount or more), which stays visible on a dark background.
vec3 ramp(float t) {
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

void main() {
  const uint cell = cellIds[gl_InstanceID];
  const int corner = (gl_VertexID & 1) == 0 ? kEdges[gl_VertexID / 2].x : kEdges[gl_VertexID / 2].y;
  const uvec3 ijk = uvec3(cell % uDims.x, (cell / uDims.x) % uDims.y, cell / (uDims.x * uDims.y));
  const vec3 p = uOrigin + uCellSize * (vec3(ijk) + vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
  gl_Position = uClipFromGrid * vec4(p, 1.0);
  const float t = clamp((float(cellCount[cell]) - 1.0) / max(uFullCount - 1.0, 1e-3), 0.0, 1.0);
  vColor = uByPopulation != 0 ? ramp(0.2 + 0.8 * t) : uColor;
}
