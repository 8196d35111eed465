// The table of models a scene can name. Each model adds one line here when it lands.
#include "scene/balls_stage.h"
#include "scene/blank.h"
#include "scene/life_stage.h"
#include "scene/ripples_stage.h"
#include "scene/stage.h"
#include "scene/swarm_stage.h"

namespace tidepool {

const std::vector<ModelEntry>& models() {
  static const std::vector<ModelEntry> table = {blankModel(), ballsModel(), ripplesModel(), swarmModel(), lifeModel()};
  return table;
}

}  // namespace tidepool
