// The scene's probes beside exported frames (sim/water/probes.h): `render --export` appends one
// row per exported frame to probes.csv in the export folder: time_s, frame, then one column per
// probe value (water::probeColumns), the same columns `validate --probe probes` writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "scene/stage.h"

namespace tidepool {

class ProbeLog {
 public:
  // Throws Error naming the file when it cannot be written.
  explicit ProbeLog(std::filesystem::path file);
  // One row; the header comes with the first. Throws Error for readings with an error (a probe the
  // model cannot measure) or other columns than the first row's.
  void write(std::uint64_t frame, double time, const ProbeReadings& readings);
  const std::filesystem::path& file() const { return m_file; }

 private:
  std::filesystem::path m_file;
  std::ofstream m_out;
  std::vector<std::string> m_columns;
  bool m_started = false;
};

}  // namespace tidepool
