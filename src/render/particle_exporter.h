// Exporting a running model's particles every K frames without stalling it: capture() starts a
// GPU copy of the model's state buffers into a staging buffer (gl/async_readback.h) and returns at
// once; poll(), once per frame, writes the frames whose copies have come back (a frame or two
// later: the simulated time travels with the copy) in order; finish() waits for the rest.
//
//   frame 0:  capture(0, t0)    poll(): nothing back yet
//   frame 1:  poll(): frame 0's copy back -> decoded -> frame_00000.vtp, particles.pvd
//
// At most kInFlight copies are outstanding; a capture beyond that first waits for the oldest.
#pragma once

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "io/export_series.h"
#include "render/export_source.h"

namespace tidepool {

// Throws Error when `model`'s export source cannot go to `format` (nullopt: nothing to export):
//   "blank has no particles: --export vtk|ply needs balls, fluid, life or swarm (ripples: vtk only)"
//   "ripples has no particles: --export ply needs balls, fluid, life or swarm (--export vtk writes
//    its heightfield)"
void checkExportable(const std::string& model, const std::optional<ExportSource>& source, io::ExportFormat format);

class ParticleExporter {
 public:
  static constexpr std::size_t kInFlight = 3;

  // Throws Error when `every` < 1 or the folder cannot be made.
  ParticleExporter(std::filesystem::path folder, io::ExportFormat format, int every);
  bool due(int frame) const { return frame % m_every == 0; }
  void capture(int frame, double time, const ExportSource& source);
  void writeObstacles(const io::TriangleMesh& mesh);  // once; nothing for an empty mesh
  void poll();    // writes the frames that have come back; throws Error naming the file that failed
  void finish();  // waits for every copy in flight and writes it

  int written() const { return m_series.written(); }
  int pending() const { return int(m_inFlight.size()); }
  const io::ExportSeries& series() const { return m_series; }
  // What it cost so far, CPU milliseconds in all: starting copies, reading back a copy that had
  // come back, waiting for one (a full queue or finish(): the read-back included), converting to
  // points, writing files; and the bytes copied.
  struct Cost {
    double captureMs = 0, readMs = 0, waitMs = 0, convertMs = 0, writeMs = 0;
    std::size_t bytes = 0;
  };
  const Cost& cost() const { return m_cost; }
  std::string summary() const;  // "exported 10 frames (vtk) to DIR: ... ms per frame"

 private:
  struct Slot {
    gl::AsyncReadback readback;
    int frame = 0;
    double time = 0;
    std::size_t bytes = 0;  // asked for
    std::function<io::ExportFrame(std::span<const std::byte>)> decode;
  };
  void write(Slot& slot, std::vector<std::byte>& bytes);
  void waitOldest();

  io::ExportSeries m_series;
  int m_every;
  std::deque<std::unique_ptr<Slot>> m_inFlight, m_free;
  std::vector<std::byte> m_bytes;
  Cost m_cost;
};

}  // namespace tidepool
