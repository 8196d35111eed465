// The table of models a scene can name. Each model adds its entry here when it lands (ballsModel() ...:
// name, summary, and how its params are read and its stage built, from its stage file).
#include "scene/balls_stage.h"
#include "scene/blank.h"
#include "scene/fluid_stage.h"
#include "scene/life_stage.h"
#include "scene/ripples_stage.h"
#include "scene/stage.h"
#include "scene/swarm_stage.h"

namespace tidepool {

const std::vector<ModelEntry>& models() {
  static const std::vector<ModelEntry> table = {blankModel(),   ballsModel(), fluidModel(),
                                                ripplesModel(), swarmModel(), lifeModel()};
  return table;
}

}  // namespace tidepool
