// What the scene pass's two obstacle shaders share: the obstacles drawn as meshes
// (obstacle_mesh.frag) or as their fixed balls (impostor.frag) take one colour, lit by the view's
// key light and the ambient light (src/render/balls_view.cpp, BallsView::drawScene sets them).
uniform vec3 uColor;      // linear RGB
uniform vec3 uLightView;  // towards the light, view space, unit
// With the environment (render/balls/environment.glsl) the sky above and the lit floor below
// light them too: the ambient share takes the colour of the half of the surroundings a surface
// faces. Without it the ambient is white (the seed's look).
uniform int uSkyLit;
uniform vec3 uSkyLight;     // linear RGB, from straight up
uniform vec3 uGroundLight;  // from straight down
uniform vec3 uUpView;       // the box's up, view space, unit

vec3 ambientLight(vec3 n) {
  return uSkyLit == 0 ? vec3(1.0) : mix(uGroundLight, uSkyLight, 0.5 + 0.5 * dot(n, uUpView));
}

out vec4 fragColor;
