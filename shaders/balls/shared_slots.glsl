// Bindings 6 and 7 of the balls' kernels. GL 4.3 guarantees 8 storage blocks per kernel, so each
// of these two binding points holds one of two arrays, by what the kernel uses:
//   HAS_OBSTACLE   6: obstaclePos (vec4, the obstacles' particles)  7: obstacleCellStart (uint)
//   COUNT_CELLS    6: nextCellCount (uint, the next step's grid)     7: nextIndexInCell (uint)
// Each binding point is declared once, and each use names its array by its own name (a #define
// of the block's member), so no kernel's text declares more blocks than it may bind.
#ifndef BALLS_SHARED_SLOTS_GLSL
#define BALLS_SHARED_SLOTS_GLSL

#if BALLS_OBST_POS != BALLS_NEXT_CELL_COUNT || BALLS_OBST_CELL_START != BALLS_NEXT_INDEX_IN_CELL
#error "balls/bindings.glsl: the two uses of bindings 6 and 7 must share them"
#endif
#if defined(COUNT_CELLS) && defined(HAS_OBSTACLE)
#error "COUNT_CELLS takes bindings 6 and 7: Balls::countsInCollide() keeps it from obstacles"
#endif

#if defined(HAS_OBSTACLE)
#define BALLS_SLOT6_ACCESS readonly
#define BALLS_SLOT6_TYPE vec4
#define BALLS_SLOT7_ACCESS readonly
#define obstaclePos slot6
#define obstacleCellStart slot7
#elif defined(COUNT_CELLS)
#define BALLS_SLOT6_ACCESS
#define BALLS_SLOT6_TYPE uint
#define BALLS_SLOT7_ACCESS writeonly
#define nextCellCount slot6
#define nextIndexInCell slot7
#endif

#ifdef BALLS_SLOT6_TYPE
layout(std430, binding = BALLS_OBST_POS) BALLS_SLOT6_ACCESS buffer Slot6 { BALLS_SLOT6_TYPE slot6[]; };
#endif
#ifdef BALLS_SLOT7_ACCESS
layout(std430, binding = BALLS_OBST_CELL_START) BALLS_SLOT7_ACCESS buffer Slot7 { uint slot7[]; };
#endif

#endif
