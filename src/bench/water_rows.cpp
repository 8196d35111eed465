// The water benchmarks' rows (water_rows.h).
#include "bench/water_rows.h"

#include <cstdlib>
#include <sstream>

#include "base/error.h"
#include "bench/bench.h"
#include "io/echo.h"

namespace tidepool::bench {

std::vector<int> parseWholeNumbers(const std::string& text, const char* option, long lo, long hi) {
  std::vector<int> out;
  std::stringstream ss(text);
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  for (std::string item; std::getline(ss, item, ',');) {
    char* end = nullptr;
    const long k = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || k < lo || k > hi)
      throw Error(std::string(option) + " '" + io::printable(item) + "' is not a whole number in " + range);
    out.push_back(int(k));
  }
  if (out.empty()) throw Error(std::string(option) + " is empty");
  return out;
}

std::vector<water::ProbeParams> loadProbes(const water::Setup& s, bool loads) {
  std::vector<water::ProbeParams> out = s.probes;
  if (!loads) return out;
  out.push_back({.kind = water::ProbeKind::Force, .wall = water::ProbeWall::MinZ});
  for (std::size_t k = 0; k < s.obstacles.size(); ++k)
    out.push_back({.kind = water::ProbeKind::Force, .obstacle = int(k)});
  return out;
}

void addFloatingBoxes(water::Setup& s, int n, bool dynamic) {
  if (s.obstacles.size() + std::size_t(n) > water::kMaxObstacles)
    throw Error("--bodies " + std::to_string(n) + ": the scene has " + std::to_string(s.obstacles.size()) +
                " obstacles and at most " + std::to_string(water::kMaxObstacles) + " fit");
  const glm::vec3 lo = glm::max(s.fillMin, s.domainMin), hi = glm::min(s.fillMax, s.domainMax);
  const int perRow = (n + 1) / 2;
  for (int i = 0; i < n; ++i) {
    water::ObstacleParams box;
    box.shape = water::Shape::Box;
    box.size = glm::vec3(0.05f * (hi.x - lo.x));
    box.centre = glm::vec3(lo.x + (hi.x - lo.x) * (float(i % perRow) + 0.5f) / float(perRow),
                           lo.y + (hi.y - lo.y) * (i < perRow ? 0.25f : 0.75f), hi.z);
    box.dynamic = dynamic;
    s.obstacles.push_back(box);
  }
}

std::vector<std::pair<int, bool>> bodyRows(const std::string& bodies, const std::string& dynamic) {
  const std::vector<int> counts = parseWholeNumbers(bodies, "--bodies", 0, long(water::kMaxObstacles));
  const std::vector<bool> moving = parseOnOff(dynamic, "--dynamic");
  std::vector<std::pair<int, bool>> rows;
  for (int n : counts)
    for (bool m : moving)
      if (n > 0 || m == moving.front()) rows.emplace_back(n, n > 0 && m);
  return rows;
}

}  // namespace tidepool::bench
