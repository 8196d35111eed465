// Binding points of the swarm model, shared by C++ (src/sim/swarm, src/render/swarm_renderer)
// and GLSL. Only #define lines: this file is valid in both languages.
#define SWARM_STATE_BINDING 0
#define SWARM_COLOR_BINDING 1
#define SWARM_IMAGE_UNIT 0
#define SWARM_MAX_ATTRACTORS 8
#define SWARM_WORK_GROUP 256
#define SWARM_ATTRIB_STATE 0
#define SWARM_ATTRIB_COLOR 1
#define SWARM_SPLAT_BINDING 2
