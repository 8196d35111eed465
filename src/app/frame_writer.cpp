#include "app/frame_writer.h"

namespace tidepool {

FrameWriter::~FrameWriter() {
  for (auto& f : m_pending)
    if (f.valid()) f.wait();
}

void FrameWriter::write(std::filesystem::path path, io::Image image) {
  while (m_pending.size() >= m_maxInFlight) {
    m_pending.front().get();
    m_pending.pop_front();
  }
  m_pending.push_back(
      std::async(std::launch::async, [p = std::move(path), img = std::move(image)] { io::writePng(p, img); }));
}

void FrameWriter::finish() {
  while (!m_pending.empty()) {
    auto f = std::move(m_pending.front());
    m_pending.pop_front();
    f.get();
  }
}

}  // namespace tidepool
