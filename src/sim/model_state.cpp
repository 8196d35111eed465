#include "sim/model_state.h"

#include <cmath>
#include <cstring>

#include "base/error.h"
#include "io/json.h"

namespace tidepool::sim {
namespace {
std::string kindName(io::EntryKind k) {
  return k == io::EntryKind::Value ? "a value" : k == io::EntryKind::Text ? "a text" : "a buffer";
}
}  // namespace

void StateVisitor::flag(const char* name, bool& b) {
  std::uint8_t u = b ? 1 : 0;
  value(name, u);
  if (u > 1) fail(std::string("entry '") + name + "' = " + std::to_string(u) + " is not a flag (0 or 1)");
  b = u == 1;
}

void StateVisitor::count(const char* name, std::size_t& n, std::size_t max) {
  std::uint64_t u = n;
  value(name, u);
  if (u > max)
    fail(std::string("entry '") + name + "' = " + std::to_string(u) + " is more than these parameters allow (" +
         std::to_string(max) + ")");
  n = std::size_t(u);
}

// Saving.

void StateSaver::clock(double& time, std::uint64_t& steps) {
  m_out.time = time;
  m_out.steps = steps;
}

void StateSaver::add(io::EntryKind kind, const char* name, const void* data, std::size_t size) {
  io::CheckpointEntry e{kind, name, std::vector<std::uint8_t>(size)};
  if (size > 0) std::memcpy(e.bytes.data(), data, size);
  m_out.entries.push_back(std::move(e));
}

void StateSaver::bytes(const char* name, void* data, std::size_t size) { add(io::EntryKind::Value, name, data, size); }

void StateSaver::text(const char* name, std::string& value, std::size_t) {
  add(io::EntryKind::Text, name, value.data(), value.size());
}

void StateSaver::buffer(const char* name, gl::Buffer& buffer, std::size_t bytes) {
  io::CheckpointEntry e{io::EntryKind::Buffer, name, std::vector<std::uint8_t>(bytes)};
  if (bytes > 0) buffer.download(e.bytes.data(), bytes);
  m_out.entries.push_back(std::move(e));
}

void StateSaver::fail(const std::string& what) const { throw Error("checkpoint not saved: " + what); }

// Loading.

void StateLoader::fail(const std::string& what) const { throw Error(m_where + ": " + what); }

void StateLoader::clock(double& time, std::uint64_t& steps) {
  if (!(m_in.time >= 0) || !std::isfinite(m_in.time)) fail("time " + std::to_string(m_in.time) + " is not a time");
  time = m_in.time;
  steps = m_in.steps;
}

const io::CheckpointEntry& StateLoader::entry(const char* name, io::EntryKind kind) {
  const io::CheckpointEntry* e = m_in.find(name);
  if (!e) fail(std::string("no entry '") + name + "' (a checkpoint of another model or build)");
  if (e->kind != kind)
    fail(std::string("entry '") + name + "' is " + kindName(e->kind) + ", expected " + kindName(kind));
  m_read.insert(name);
  return *e;
}

void StateLoader::bytes(const char* name, void* data, std::size_t size) {
  const io::CheckpointEntry& e = entry(name, io::EntryKind::Value);
  if (e.bytes.size() != size)
    fail(std::string("entry '") + name + "' holds " + std::to_string(e.bytes.size()) + " bytes, this build's has " +
         std::to_string(size));
  if (size > 0) std::memcpy(data, e.bytes.data(), size);
}

void StateLoader::text(const char* name, std::string& value, std::size_t maxBytes) {
  const io::CheckpointEntry& e = entry(name, io::EntryKind::Text);
  if (e.bytes.size() > maxBytes)
    fail(std::string("entry '") + name + "' holds " + std::to_string(e.bytes.size()) + " bytes, at most " +
         std::to_string(maxBytes));
  value.assign(e.bytes.begin(), e.bytes.end());
}

void StateLoader::buffer(const char* name, gl::Buffer& buffer, std::size_t bytes) {
  const io::CheckpointEntry& e = entry(name, io::EntryKind::Buffer);
  if (e.bytes.size() != bytes)
    fail(std::string("buffer '") + name + "' holds " + std::to_string(e.bytes.size()) +
         " bytes, the scene's state at these parameters has " + std::to_string(bytes));
  if (buffer.size() < bytes)
    fail(std::string("buffer '") + name + "' of " + std::to_string(bytes) + " bytes does not fit the model's " +
         std::to_string(buffer.size()));
  if (bytes > 0) buffer.upload(e.bytes.data(), bytes);
}

void StateLoader::finish() const {
  for (const io::CheckpointEntry& e : m_in.entries)
    if (!m_read.count(e.name)) fail("entry '" + io::printable(e.name) + "' is not part of this scene's state");
}

}  // namespace tidepool::sim
