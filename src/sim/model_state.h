// A model's state beyond its parameters, declared once for saving and loading (as ParamVisitor
// declares parameters): the clock, counters, RNG state and GPU buffers a later step reads.
//
//   void Balls::visitOwnState(sim::StateVisitor& v) {
//     v.clock(m_time, steps);
//     v.count("model.count", m_count, m_capacity);   // loading: at most the capacity, else an error
//     v.value("model.tap_next_layer", m_tapNextLayer);
//     v.flag("model.acc_valid", m_accValid);
//     if (m_accValid) v.buffer("model.accelerations", m_acc, m_count * sizeof(glm::vec4));
//   }
//
// StateSaver copies each into an io::Checkpoint entry (buffers read back from the GPU);
// StateLoader copies them back, checking every size against what the model expects now, so a
// checkpoint of another size, model or build is refused with one line naming the entry.
#pragma once

#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "gl/buffer.h"
#include "io/checkpoint_file.h"

namespace tidepool::sim {

class StateVisitor {
 public:
  virtual ~StateVisitor() = default;
  virtual bool loading() const = 0;
  virtual void clock(double& time, std::uint64_t& steps) = 0;                         // the file's time and step count
  virtual void bytes(const char* name, void* data, std::size_t size) = 0;             // a fixed-size value
  virtual void text(const char* name, std::string& value, std::size_t maxBytes) = 0;  // JSON, an RNG's state
  virtual void buffer(const char* name, gl::Buffer& buffer, std::size_t bytes) = 0;   // its first `bytes`
  [[noreturn]] virtual void fail(const std::string& what) const = 0;                  // "<file>: <what>" (loading)
  // Loading: whether the file holds the entry (files written before an entry was added lack it).
  virtual bool has(const char* /*name*/) const { return true; }

  template <class T>
  void value(const char* name, T& v) {
    static_assert(std::is_trivially_copyable_v<T> && !std::is_same_v<T, bool> && !std::is_enum_v<T>,
                  "flag() for bools, choice() for enums");
    bytes(name, &v, sizeof v);
  }
  void flag(const char* name, bool& b);
  // A count that may not exceed `max` (a capacity): loading more is refused, naming both.
  void count(const char* name, std::size_t& n, std::size_t max);
  // An enumeration stored as its index, checked against the number of names.
  template <class E>
  void choice(const char* name, E& e, std::size_t names) {
    std::uint32_t index = std::uint32_t(e);
    value(name, index);
    if (index >= names) fail(std::string("entry '") + name + "' = " + std::to_string(index) + " is not a valid choice");
    e = E(index);
  }
  // A vector of plain values, at most maxSize of them.
  template <class T>
  void array(const char* name, std::vector<T>& items, std::size_t maxSize) {
    std::size_t n = items.size();
    count((std::string(name) + ".size").c_str(), n, maxSize);
    items.resize(n);
    if (n > 0) bytes(name, items.data(), n * sizeof(T));
  }
};

// Fills `out`'s clock and entries.
class StateSaver final : public StateVisitor {
 public:
  explicit StateSaver(io::Checkpoint& out) : m_out(out) {}
  bool loading() const override { return false; }
  void clock(double& time, std::uint64_t& steps) override;
  void bytes(const char* name, void* data, std::size_t size) override;
  void text(const char* name, std::string& value, std::size_t maxBytes) override;
  void buffer(const char* name, gl::Buffer& buffer, std::size_t bytes) override;
  [[noreturn]] void fail(const std::string& what) const override;

 private:
  void add(io::EntryKind kind, const char* name, const void* data, std::size_t size);
  io::Checkpoint& m_out;
};

// Reads `in`'s clock and entries back; errors start with `where` (the file).
class StateLoader final : public StateVisitor {
 public:
  StateLoader(const io::Checkpoint& in, std::string where) : m_in(in), m_where(std::move(where)) {}
  bool loading() const override { return true; }
  bool has(const char* name) const override { return m_in.find(name) != nullptr; }
  void clock(double& time, std::uint64_t& steps) override;
  void bytes(const char* name, void* data, std::size_t size) override;
  void text(const char* name, std::string& value, std::size_t maxBytes) override;
  void buffer(const char* name, gl::Buffer& buffer, std::size_t bytes) override;
  [[noreturn]] void fail(const std::string& what) const override;
  void finish() const;  // every entry of the file was read: refuses entries this state does not have

 private:
  const io::CheckpointEntry& entry(const char* name, io::EntryKind kind);
  const io::Checkpoint& m_in;
  std::string m_where;
  std::set<std::string> m_read;
};

}  // namespace tidepool::sim
