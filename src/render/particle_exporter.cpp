#include "render/particle_exporter.h"

#include <chrono>
#include <cstdio>

#include "base/error.h"

namespace tidepool {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

io::ExportSeries makeSeries(std::filesystem::path folder, io::ExportFormat format, int every) {
  if (every < 1) throw Error("--every " + std::to_string(every) + " must be at least 1 (export every K-th frame)");
  return io::ExportSeries(std::move(folder), format);
}

}  // namespace

void checkExportable(const std::string& model, const std::optional<ExportSource>& source, io::ExportFormat format) {
  if (!source)
    throw Error(model + " has no particles: --export vtk|ply needs balls, fluid, life or swarm (ripples: vtk only)");
  if (format == io::ExportFormat::Obj)
    throw Error(model + " particles have no OBJ form: export them as vtk or ply (--export surface writes OBJ meshes)");
  if (source->heightField && format != io::ExportFormat::Vtk)
    throw Error(
        model +
        " has no particles: --export ply needs balls, fluid, life or swarm (--export vtk writes its heightfield)");
}

ParticleExporter::ParticleExporter(std::filesystem::path folder, io::ExportFormat format, int every)
    : m_series(makeSeries(std::move(folder), format, every)), m_every(every) {}

void ParticleExporter::capture(int frame, double time, const ExportSource& source) {
  if (m_inFlight.size() >= kInFlight) waitOldest();
  const auto start = Clock::now();
  std::unique_ptr<Slot> slot;
  if (m_free.empty()) {
    slot = std::make_unique<Slot>();
  } else {
    slot = std::move(m_free.front());
    m_free.pop_front();
  }
  slot->frame = frame;
  slot->time = time;
  slot->bytes = source.bytes();
  slot->decode = source.decode;
  slot->readback.request(source.ranges);
  m_inFlight.push_back(std::move(slot));
  m_cost.captureMs += msSince(start);
  m_cost.bytes += source.bytes();
}

void ParticleExporter::writeObstacles(const io::TriangleMesh& mesh) {
  if (!mesh.triangles.empty()) m_series.writeObstacles(mesh);
}

void ParticleExporter::write(Slot& slot, std::vector<std::byte>& bytes) {
  if (bytes.size() != slot.bytes)
    throw Error("export: the GPU copy of frame " + std::to_string(slot.frame) + " did not come back (" +
                std::to_string(bytes.size()) + " of " + std::to_string(slot.bytes) + " bytes)");
  auto start = Clock::now();
  io::ExportFrame data = slot.decode(bytes);
  std::visit([&](auto& d) { d.time = slot.time; }, data);
  m_cost.convertMs += msSince(start);
  start = Clock::now();
  m_series.write(slot.frame, data);
  m_cost.writeMs += msSince(start);
}

void ParticleExporter::poll() {
  while (!m_inFlight.empty()) {
    const auto start = Clock::now();
    if (!m_inFlight.front()->readback.poll(m_bytes)) return;
    m_cost.readMs += msSince(start);
    std::unique_ptr<Slot> slot = std::move(m_inFlight.front());
    m_inFlight.pop_front();
    write(*slot, m_bytes);
    m_free.push_back(std::move(slot));
  }
}

void ParticleExporter::waitOldest() {
  const auto start = Clock::now();
  std::unique_ptr<Slot> slot = std::move(m_inFlight.front());
  m_inFlight.pop_front();
  slot->readback.wait(m_bytes);
  m_cost.waitMs += msSince(start);  // the read-back included
  write(*slot, m_bytes);
  m_free.push_back(std::move(slot));
}

void ParticleExporter::finish() {
  while (!m_inFlight.empty()) waitOldest();
}

std::string ParticleExporter::summary() const {
  const double n = std::max(1, written());
  char line[512];
  std::snprintf(line, sizeof line,
                "exported %d frames (%s) to %s: per frame %.2f ms to start the copy, %.2f ms to read it back (%.2f ms "
                "of them waiting), %.2f ms to convert, %.2f ms to write (%.2f MB copied)",
                written(), io::kExportFormatNames[std::size_t(m_series.format())],
                std::filesystem::absolute(m_series.folder()).string().c_str(), m_cost.captureMs / n,
                (m_cost.readMs + m_cost.waitMs) / n, m_cost.waitMs / n, m_cost.convertMs / n, m_cost.writeMs / n,
                double(m_cost.bytes) / n / 1e6);
  return line;
}

}  // namespace tidepool
