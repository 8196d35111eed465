// Verlet neighbour lists (Params::neighbours = lists), shared by C++ and GLSL: only #define lines.
// One uint storage block, column-major: entry c of ball i at c * stride + i (stride = the balls'
// capacity), so that a warp's loads of one entry are coalesced:
//   columns 0..2   the ball's position at the last build (float bits): its displacement's origin
//   column 3       how many balls lay within 2r + skin then (more than the capacity: the collide
//                  walks the grid for that ball instead, and the next step rebuilds)
//   columns 4..    their indices, at most columns - 4
// After columns * stride words come the control words, at uControl:
#define BALLS_LIST_FIRST 4             // column of the first neighbour
#define BALLS_LIST_SLOTS 64            // displacement boxes, one per (work group mod 64): 6 words each,
                                       // min xyz then max xyz of x - x_build as order-preserving bits
#define BALLS_LIST_OVERFLOW 384        // balls with more neighbours than the capacity at the last build
#define BALLS_LIST_REBUILDS 385        // builds so far (the gate counts them)
#define BALLS_LIST_STEPS 386           // gated steps so far
#define BALLS_LIST_CONTROL_WORDS 388
