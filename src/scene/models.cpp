// The table of models a scene can name. Each model adds one line here when it lands.
#include "scene/balls_stage.h"
#include "scene/blank.h"
#include "scene/life_stage.h"
#include "scene/ripples_stage.h"
#include "scene/stage.h"
#include "scene/swarm_stage.h"

namespace tidepool {

const std::vector<ModelEntry>& models() {
  static const std::vector<ModelEntry> table = {
      {"blank", "no simulation: clears to a colour (the shell before any model)", parseBlankParams, createBlankStage},
      {"balls", "water as equal balls colliding: grid neighbours, three contact laws, three integrators",
       parseBallsParams, createBallsStage},
      {"ripples", "heightfield water: wave equation or the seed's spring model, 2D refraction view", parseRipplesParams,
       createRipplesStage},
      {"swarm", "millions of 2D particles pulled by animated attractors, one following the mouse", parseSwarmParams,
       createSwarmStage},
      {"life", "particle life: species with asymmetric forces, glow + HDR view, shareable rules", parseLifeParams,
       createLifeStage},
  };
  return table;
}

}  // namespace tidepool
