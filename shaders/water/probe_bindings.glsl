// Binding points and sizes of the water probes' kernels (shaders/water/gauge.comp), which
// water::Probes (src/sim/water/probes.cpp) runs; shared by C++ and GLSL. Only #define lines.
#define PROBE_GROUP_SIZE 128  // invocations per work group
#define PROBE_MAX_GAUGES 16   // gauges per dispatch (= water::kMaxProbes)
#define PROBE_POS 0           // the particles' positions, one window of them
#define PROBE_PARTIALS 1      // per work group: PROBE_MAX_GAUGES sums
