// Screen-space derivatives in compute shaders, taken the way a fragment shader's 2x2 quads take
// them, so that textureGrad() picks the mip level texture() would pick when rasterising.
// The work group must be square and even-sided with one invocation per pixel (x right, y up);
// every invocation of the group must call quadGradient() (it holds a barrier).
#ifndef RENDER_RIPPLES_QUAD_GRADIENT_GLSL
#define RENDER_RIPPLES_QUAD_GRADIENT_GLSL

shared vec3 sQuad[gl_WorkGroupSize.x * gl_WorkGroupSize.y];  // xy: value, z: 1 where valid

// d(value)/dx and d(value)/dy from the pixel's quad neighbours. Where the horizontal (vertical)
// neighbour has no valid value, the quad's other row (column) is used; where that fails too, 0.
void quadGradient(vec2 value, bool valid, out vec2 ddx, out vec2 ddy) {
  const uvec2 l = gl_LocalInvocationID.xy;
  const uint w = gl_WorkGroupSize.x;
  sQuad[l.y * w + l.x] = vec3(value, valid ? 1.0 : 0.0);
  barrier();
  const uvec2 q = l & ~1u;  // the quad's bottom-left pixel
  const vec3 p00 = sQuad[q.y * w + q.x], p10 = sQuad[q.y * w + q.x + 1u];
  const vec3 p01 = sQuad[(q.y + 1u) * w + q.x], p11 = sQuad[(q.y + 1u) * w + q.x + 1u];
  const bool top = l.y != q.y, right = l.x != q.x;
  const vec3 rowA = top ? p01 : p00, rowB = top ? p11 : p10;          // own row: left, right
  const vec3 otherA = top ? p00 : p01, otherB = top ? p10 : p11;      // other row
  const vec3 colA = right ? p10 : p00, colB = right ? p11 : p01;      // own column: bottom, top
  const vec3 otherC = right ? p00 : p10, otherD = right ? p01 : p11;  // other column
  ddx = rowA.z * rowB.z > 0.0 ? rowB.xy - rowA.xy : otherA.z * otherB.z > 0.0 ? otherB.xy - otherA.xy : vec2(0.0);
  ddy = colA.z * colB.z > 0.0 ? colB.xy - colA.xy : otherC.z * otherD.z > 0.0 ? otherD.xy - otherC.xy : vec2(0.0);
}

#endif
