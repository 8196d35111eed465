#version 430 core
// Swarm particles as points: the state buffer is the vertex buffer (aState = pos.xy NDC, vel.zw).
#include "swarm/bindings.glsl"
#include "render/swarm/color.glsl"

layout(location = SWARM_ATTRIB_STATE) in vec4 aState;
layout(location = SWARM_ATTRIB_COLOR) in vec4 aColor;  // image mode: per-particle colour

uniform int uColorMode;    // 0: uColor, 1: aColor, 2: velocity direction
uniform vec3 uColor;
uniform float uPointSize;  // pixels

out vec3 vColor;

void main() {
  gl_Position = vec4(aState.xy, 0.0, 1.0);
  gl_PointSize = uPointSize;
  if (uColorMode == 1)
    vColor = aColor.rgb;
  else if (uColorMode == 2)
    vColor = hueRamp(0.5 + 0.5 * atan(aState.w, aState.z) / 3.14159265);
  else
    vColor = uColor;
}
