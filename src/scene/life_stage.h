// The life scene: particle life (sim/life), its glow/HDR view and the article's controls —
// left drag pushes particles (a Gaussian brush of a sixteenth of the view width), right drag
// pans, the wheel zooms about the cursor (gliding there); keys C centre the view, N new random
// rules, W saves the rules to particle-life-system.json (S, as in the original, is the app's
// hide-panel key); R, the app's restart, draws new random particles with the same rules.
// Rules come from the scene's "rules" (a rules JSON path, a preset name from assets/rules, or a
// share code) or are generated from its seed; a rules JSON dropped on the window replaces them.
#pragma once

#include "scene/stage.h"

namespace tidepool {

ModelEntry lifeModel();  // "life" in scene files

}  // namespace tidepool
