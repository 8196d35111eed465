#include "io/assets.h"

#include <cstdlib>
#include <string>

#include "base/error.h"
#include "base/source_dir.h"
#include "io/echo.h"

namespace tidepool::io {
namespace fs = std::filesystem;

fs::path findAssetDir() {
  if (const char* env = std::getenv("TIDEPOOL_ASSET_DIR")) {
    std::error_code ec;
    if (!fs::is_directory(env, ec))
      throw Error("asset directory '" + shownPath(env) + "' (from TIDEPOOL_ASSET_DIR) not found");
    return env;
  }
  std::error_code ec;
  const fs::path exeDir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (const fs::path& c : {exeDir / "assets", exeDir / ".." / "assets", sourceDir() / "assets"})
    if (fs::is_directory(c / "scenes", ec)) return fs::weakly_canonical(c);
  throw Error("asset directory not found next to the executable or in the source tree; set TIDEPOOL_ASSET_DIR");
}

}  // namespace tidepool::io
