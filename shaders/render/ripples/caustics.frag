#version 430 core
// Each light point adds its share, so that flat water lights every floor texel with 1.
uniform float uWeight;  // floor texels / light points
out vec4 fragColor;

void main() { fragColor = vec4(uWeight, 0.0, 0.0, 1.0); }
