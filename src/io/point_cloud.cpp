#include "io/point_cloud.h"

#include "base/error.h"

namespace tidepool::io {

void checkPointCloud(const PointCloud& cloud) {
  if (cloud.positions.size() % 3 != 0)
    throw Error("point cloud: " + std::to_string(cloud.positions.size()) + " position values are not x y z triples");
  for (const PointField& f : cloud.fields)
    if (f.parts.empty() || f.values.size() != cloud.size() * f.components())
      throw Error("point cloud: field '" + f.name + "' has " + std::to_string(f.values.size()) + " values for " +
                  std::to_string(cloud.size()) + " points of " + std::to_string(f.components()) + " components");
}

void checkHeightField(const HeightField& grid) {
  if (grid.width < 1 || grid.height < 1)
    throw Error("heightfield: " + std::to_string(grid.width) + " x " + std::to_string(grid.height) + " points");
  for (const PointField& f : grid.fields)
    if (f.parts.empty() || f.values.size() != grid.size() * f.components())
      throw Error("heightfield: field '" + f.name + "' has " + std::to_string(f.values.size()) + " values for " +
                  std::to_string(grid.size()) + " points of " + std::to_string(f.components()) + " components");
}

}  // namespace tidepool::io
