#include "base/source_dir.h"

namespace tidepool {

std::filesystem::path sourceDir() { return TIDEPOOL_SOURCE_DIR; }

}  // namespace tidepool
