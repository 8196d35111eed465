// VTK XML files that ParaView opens: PolyData (.vtp) of points or triangles, and a collection
// (.pvd) that makes frames one time series. Arrays are raw binary in one appended block, each
// preceded by its byte count as a UInt64 (header_type="UInt64"), little-endian:
//
//   <VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
//    <PolyData><Piece NumberOfPoints="2" NumberOfVerts="2" ...>
//     <PointData><DataArray type="Float32" Name="velocity" NumberOfComponents="3" format="appended" offset="0"/>
//     <Points><DataArray type="Float32" Name="Points" NumberOfComponents="3" ... offset="32"/>
//     <Verts><DataArray type="Int32" Name="connectivity" .../><DataArray type="Int32" Name="offsets" .../>
//    ...
//    <AppendedData encoding="raw">_[u64 24][vx0 vy0 vz0 vx1 vy1 vz1][u64 24][x0 ...][u64 8][0 1][u64 8][1 2]
//
// Points are one vertex cell each (connectivity i, offsets i + 1: where each cell ends).
// A heightfield is ImageData (.vti): WholeExtent="0 W-1 0 H-1 0 0", Origin, Spacing, and its
// fields as point data in the same appended block (ParaView: Warp By Scalar on "height").
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/obj.h"
#include "io/point_cloud.h"

namespace tidepool::io {

std::vector<std::uint8_t> vtpBytes(const PointCloud& cloud);   // throws Error (checkPointCloud, over 2^31 points)
std::vector<std::uint8_t> vtpBytes(const TriangleMesh& mesh);  // points and triangle polys
void writeVtp(const std::filesystem::path& file, const PointCloud& cloud);  // replaceFile (io/output_file.h)
void writeVtp(const std::filesystem::path& file, const TriangleMesh& mesh);
std::vector<std::uint8_t> vtiBytes(const HeightField& grid);  // throws Error (checkHeightField)
void writeVti(const std::filesystem::path& file, const HeightField& grid);

// A .pvd collection: one DataSet per frame, file names relative to the collection's folder.
//   <DataSet timestep="0.5" group="" part="0" file="frame_00030.vtp"/>
// Each add() rewrites the whole collection through replaceFile, so a run killed at any point
// leaves a valid series of the frames written so far.
class PvdCollection {
 public:
  explicit PvdCollection(std::filesystem::path file) : m_file(std::move(file)) {}
  void add(double time, const std::string& dataFile);  // throws Error naming the .pvd
  std::string text() const;                            // the collection as it is now
  std::size_t size() const { return m_entries.size(); }

 private:
  std::filesystem::path m_file;
  std::vector<std::pair<double, std::string>> m_entries;
};

}  // namespace tidepool::io
