// What the scene pass's two obstacle shaders share: the obstacles drawn as meshes
// (obstacle_mesh.frag) or as their fixed balls (impostor.frag) take one colour, lit by the view's
// key light (src/render/balls_view.cpp, BallsView::drawScene sets both).
uniform vec3 uColor;      // linear RGB
uniform vec3 uLightView;  // towards the light, view space, unit

out vec4 fragColor;
