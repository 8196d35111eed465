#version 430 core
// Glossy ball (render/ripples/ball_shading.glsl).
#include "render/ripples/ball_shading.glsl"

uniform vec3 uColor;   // linear RGB
uniform vec3 uSunDir;  // towards the sun
uniform vec3 uEye;
uniform int uOrtho;     // 1: orthographic camera, every view ray along uViewDir
uniform vec3 uViewDir;  // world, unit
in vec3 vNormal;
in vec3 vWorld;
out vec4 fragColor;

void main() { fragColor = vec4(ballColor(uColor, normalize(vNormal), uOrtho != 0 ? -uViewDir : normalize(uEye - vWorld), uSunDir), 1.0); }
