#version 430 core
// Grid cells view: the cell edges' colour from grid_cells.vert.
in vec3 vColor;
layout(location = 0) out vec4 fragColor;

void main() { fragColor = vec4(vColor, 1.0); }
