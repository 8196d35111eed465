#include "sim/divergence.h"

#include <cstdio>
#include <cstring>

namespace tidepool {
namespace {
CheckCycle::Words words(const std::vector<std::byte>& bytes) {
  CheckCycle::Words w{};
  std::memcpy(w.data(), bytes.data(), std::min(bytes.size(), sizeof w));
  return w;
}
}  // namespace

float healthFloat(std::uint32_t word) {
  float value = 0;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

DivergenceReport divergenceReport(const std::string& model, double time, const std::string& what,
                                  const std::string& method, bool hasGood) {
  char at[32];
  std::snprintf(at, sizeof at, "%.4f", time);
  return {
      model + " diverged by t = " + at + " s: " + what + " (" + method + ")" +
          (hasGood ? "; halve the time step and resume from the last good state" : "; halve the time step and reset"),
      time};
}

void CheckCycle::frame(double time, bool allowed, const Judge& judge, const std::function<void()>& start,
                       const gl::Buffer& health) {
  std::vector<std::byte> bytes;
  if (m_readback.poll(bytes)) judge(words(bytes), m_time);
  if (m_readback.pending() || ++m_frames < m_interval || !allowed) return;
  m_frames = 0;
  start();
  m_time = time;
  m_readback.request(health, health.size());
}

void CheckCycle::flush(const Judge& judge) {
  if (!m_readback.pending()) return;
  std::vector<std::byte> bytes;
  m_readback.wait(bytes);
  judge(words(bytes), m_time);
}

void CheckCycle::restart() {
  m_frames = 0;
  std::vector<std::byte> discard;
  m_readback.wait(discard);  // a check of the old state must not judge the new one
}

}  // namespace tidepool
