// Accuracy data in tests: the shipped scenes whose data has not shipped yet, and a scoped assets
// folder (TIDEPOOL_ASSET_DIR) so that method and model auto read fixture rows through the real
// code path (<assets>/accuracy/<study>.csv).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "io/json.h"
#include "scene/auto/auto.h"

namespace tidepool::test {

// The accuracy file a "model": "auto" scene reads that assets/accuracy/ lacks (the water studies
// are measured on the GPU machine and shipped later); "" when the scene has what it reads.
inline std::string missingAccuracyData(const std::filesystem::path& scene) {
  const io::Json json = io::readJsonFile(scene);
  if (!json.is_object() || json.value("model", "") != kAutoModel || !json.contains("accuracy")) return "";
  for (const auto& [key, value] : json.at("accuracy").items())
    for (const automethod::Metric& m : automethod::metrics())
      if (m.model == "water" && m.key == key)
        for (const std::string& study : m.studies)
          if (const auto file = accuracyDir() / (study + ".csv"); !std::filesystem::exists(file)) return file.string();
  return "";
}

// Sets TIDEPOOL_ASSET_DIR for the life of the object (this process only), then restores it.
class ScopedAssetDir {
 public:
  explicit ScopedAssetDir(const std::filesystem::path& dir) {
    if (const char* old = std::getenv("TIDEPOOL_ASSET_DIR")) m_old = old;
    ::setenv("TIDEPOOL_ASSET_DIR", dir.c_str(), 1);
  }
  ~ScopedAssetDir() {
    if (m_old)
      ::setenv("TIDEPOOL_ASSET_DIR", m_old->c_str(), 1);
    else
      ::unsetenv("TIDEPOOL_ASSET_DIR");
  }
  ScopedAssetDir(const ScopedAssetDir&) = delete;
  ScopedAssetDir& operator=(const ScopedAssetDir&) = delete;

 private:
  std::optional<std::string> m_old;
};

}  // namespace tidepool::test
