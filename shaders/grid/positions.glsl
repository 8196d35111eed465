// The particle arrays the grid reads and moves (src/grid/grid.h, GridParams::layout):
//   HALF_POSITIONS = 0: positions vec4 (xyz + w); reordered arrays of 16-byte elements
//   HALF_POSITIONS = 1: 2D positions uvec2 (packHalf2x16(xy), any word); 8-byte elements
// Elements are moved as unsigned words, so every bit pattern arrives unchanged. A kernel that
// does not read the positions at their binding (the reorder passes read the cells the count pass
// stored, the rank-scatter reads the positions as its first source array) defines
// GRID_NO_POSITIONS_BLOCK and gets no Positions block, only elementPosition().
#ifndef GRID_POSITIONS_GLSL
#define GRID_POSITIONS_GLSL

#ifndef HALF_POSITIONS
#define HALF_POSITIONS 0
#endif

#if HALF_POSITIONS
#define GridElement uvec2
#define GRID_POSITION_TYPE uvec2
vec3 elementPosition(uvec2 e) { return vec3(unpackHalf2x16(e.x), 0.0); }
#else
#define GridElement uvec4
#define GRID_POSITION_TYPE vec4
vec3 elementPosition(uvec4 e) { return uintBitsToFloat(e.xyz); }
#endif

#ifndef GRID_NO_POSITIONS_BLOCK
layout(std430, binding = GRID_POSITIONS) readonly buffer Positions { GRID_POSITION_TYPE positions[]; };
#if HALF_POSITIONS
vec3 particlePosition(uint i) { return elementPosition(positions[i]); }
#else
vec3 particlePosition(uint i) { return positions[i].xyz; }
#endif
#endif

#endif
