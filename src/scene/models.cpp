// The table of models a scene can name. Each model adds one line here when it lands.
#include "scene/blank.h"
#include "scene/stage.h"

namespace tidepool {

const std::vector<ModelEntry>& models() {
  static const std::vector<ModelEntry> table = {
      {"blank", "no simulation: clears to a colour (the shell before any model)", createBlankStage},
  };
  return table;
}

}  // namespace tidepool
