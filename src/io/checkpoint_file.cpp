#include "io/checkpoint_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <set>

#include "base/error.h"
#include "io/checkpoint_path.h"
#include "io/echo.h"
#include "io/json.h"
#include "io/limits.h"

namespace tidepool::io {
namespace {

std::array<std::uint32_t, 256> crcTable() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}

std::string kindName(EntryKind k) {
  switch (k) {
    case EntryKind::Value: return "value";
    case EntryKind::Text: return "text";
    case EntryKind::Buffer: return "buffer";
  }
  return "?";
}

// Appends little-endian fields.
class Out {
 public:
  std::vector<std::uint8_t> bytes;
  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(std::uint8_t(v >> (8 * i)));
  }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes.push_back(std::uint8_t(v >> (8 * i)));
  }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void raw(const void* data, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes.insert(bytes.end(), p, p + n);
  }
  void str(const std::string& s, std::size_t limit, const char* field) {
    if (s.size() > limit)
      throw Error(std::string("checkpoint: ") + field + " of " + std::to_string(s.size()) + " bytes, at most " +
                  std::to_string(limit));
    u32(std::uint32_t(s.size()));
    raw(s.data(), s.size());
  }
};

// Reads little-endian fields, checking each against the bytes left; errors name the field and offset.
class In {
 public:
  In(std::span<const std::uint8_t> bytes, std::size_t base, std::string where)
      : m_bytes(bytes), m_base(base), m_where(std::move(where)) {}

  std::size_t left() const { return m_bytes.size() - m_at; }
  std::size_t offset() const { return m_base + m_at; }  // in the file
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw Error(m_where + ": " + field + " at byte " + std::to_string(offset()) + ": " + what);
  }
  void need(std::uint64_t n, const std::string& field) const {
    if (n > left())
      fail(field,
           "needs " + std::to_string(n) + " bytes, only " + std::to_string(left()) + " are left (a damaged file)");
  }
  std::uint64_t uint(int bytes, const std::string& field) {
    need(std::size_t(bytes), field);
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t(m_bytes[m_at + std::size_t(i)]) << (8 * i);
    m_at += std::size_t(bytes);
    return v;
  }
  double f64(const std::string& field) { return std::bit_cast<double>(uint(8, field)); }
  // A length, checked against its limit and the bytes left before anything is allocated.
  std::size_t length(int bytes, std::size_t limit, const std::string& field) {
    const std::uint64_t n = uint(bytes, field + " length");
    if (n > limit) {
      m_at -= std::size_t(bytes);
      fail(field, "length " + std::to_string(n) + " is more than the limit " + std::to_string(limit));
    }
    need(std::size_t(n), field);
    return std::size_t(n);
  }
  std::string str(std::size_t limit, const std::string& field) {
    const std::size_t n = length(4, limit, field);
    std::string s(reinterpret_cast<const char*>(m_bytes.data() + m_at), n);
    m_at += n;
    return s;
  }
  std::vector<std::uint8_t> blob(std::size_t n) {
    std::vector<std::uint8_t> v(m_bytes.begin() + std::ptrdiff_t(m_at), m_bytes.begin() + std::ptrdiff_t(m_at + n));
    m_at += n;
    return v;
  }

 private:
  std::span<const std::uint8_t> m_bytes;
  std::size_t m_at = 0, m_base;
  std::string m_where;
};

std::string systemError() { return std::strerror(errno); }

void writeAll(int fd, const std::uint8_t* data, std::size_t n, const std::filesystem::path& tmp) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw Error("cannot write checkpoint '" + shownPath(tmp) + "': " + systemError());
    data += w;
    n -= std::size_t(w);
  }
}

// Exactly n bytes from `fd` at file offset `at` on: a file that shrinks while it is read is truncated.
void readAll(int fd, std::uint8_t* data, std::size_t n, std::uint64_t at, const std::string& where) {
  while (n > 0) {
    const ssize_t r = ::read(fd, data, std::min<std::size_t>(n, std::size_t(1) << 30));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw Error("cannot read checkpoint '" + where + "': " + systemError());
    if (r == 0)
      throw Error(where + ": truncated at byte " + std::to_string(at) + " (the file shrank while it was read)");
    data += r;
    at += std::uint64_t(r);
    n -= std::size_t(r);
  }
}

}  // namespace

const CheckpointEntry* Checkpoint::find(const std::string& name) const {
  for (const CheckpointEntry& e : entries)
    if (e.name == name) return &e;
  return nullptr;
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
  static const std::array<std::uint32_t, 256> table = crcTable();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::uint8_t b : bytes) c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::vector<std::uint8_t> encodeCheckpoint(const Checkpoint& c) {
  if (c.entries.size() > kMaxEntries)
    throw Error("checkpoint: " + std::to_string(c.entries.size()) + " entries, at most " + std::to_string(kMaxEntries));
  Out payload;
  payload.str(c.model, kMaxModelName, "model name");
  payload.str(c.scene, kMaxSceneName, "scene name");
  payload.str(c.params, kMaxParamsText, "parameters");
  payload.f64(c.time);
  payload.u64(c.steps);
  payload.u32(std::uint32_t(c.entries.size()));
  for (const CheckpointEntry& e : c.entries) {
    payload.u8(std::uint8_t(e.kind));
    payload.str(e.name, kMaxEntryName, "entry name");
    payload.u64(e.bytes.size());
    payload.raw(e.bytes.data(), e.bytes.size());
  }
  Out file;
  file.raw(kCheckpointMagic, sizeof kCheckpointMagic);
  file.u32(kCheckpointVersion);
  file.u32(crc32(payload.bytes));
  file.u64(payload.bytes.size());
  file.bytes.insert(file.bytes.end(), payload.bytes.begin(), payload.bytes.end());
  return std::move(file.bytes);
}

namespace {
struct Header {
  std::uint32_t checksum = 0;
  std::uint64_t payloadBytes = 0;
};

// The header's magic, version and stated size, from its first bytes (`head`, up to 24) and the
// size of the whole file: a file can be refused before its payload is read.
Header checkHeader(std::span<const std::uint8_t> head, std::uint64_t fileBytes, const std::string& where) {
  if (head.size() < sizeof kCheckpointMagic || std::memcmp(head.data(), kCheckpointMagic, sizeof kCheckpointMagic))
    throw Error(where + ": not a tidepool checkpoint (the file does not start with \"TIDEPOOL\")");
  const auto truncatedHeader = [&] {
    return Error(where + ": truncated at byte " + std::to_string(fileBytes) + " of the " +
                 std::to_string(kCheckpointHeaderBytes) + "-byte header");
  };
  if (head.size() < sizeof kCheckpointMagic + 4) throw truncatedHeader();
  In header(head, 0, where);
  header.blob(sizeof kCheckpointMagic);
  const std::uint64_t version = header.uint(4, "format version");
  if (version != kCheckpointVersion)
    throw Error(where + ": format version " + std::to_string(version) + ", this build reads " +
                std::to_string(kCheckpointVersion));
  if (head.size() < kCheckpointHeaderBytes) throw truncatedHeader();
  Header h;
  h.checksum = std::uint32_t(header.uint(4, "checksum"));
  h.payloadBytes = header.uint(8, "payload size");
  const std::uint64_t total = h.payloadBytes + kCheckpointHeaderBytes;
  if (h.payloadBytes > fileBytes || total > fileBytes)
    throw Error(where + ": truncated at byte " + std::to_string(fileBytes) + " of " +
                (h.payloadBytes > (std::uint64_t(1) << 60) ? std::string("a corrupt size") : std::to_string(total)));
  if (total < fileBytes)
    throw Error(where + ": " + std::to_string(fileBytes - total) + " bytes after the end of the checkpoint (byte " +
                std::to_string(total) + ")");
  return h;
}
}  // namespace

Checkpoint parseCheckpoint(std::span<const std::uint8_t> bytes, const std::string& where) {
  const std::uint32_t checksum =
      checkHeader(bytes.first(std::min(bytes.size(), kCheckpointHeaderBytes)), bytes.size(), where).checksum;
  const std::span<const std::uint8_t> payload = bytes.subspan(kCheckpointHeaderBytes);
  if (const std::uint32_t actual = crc32(payload); actual != checksum) {
    char what[160];
    std::snprintf(what, sizeof what, ": checksum mismatch (payload corrupt: CRC-32 %08x, the header says %08x)", actual,
                  checksum);
    throw Error(where + what);
  }

  In in(payload, kCheckpointHeaderBytes, where);
  Checkpoint c;
  c.model = in.str(kMaxModelName, "model name");
  c.scene = in.str(kMaxSceneName, "scene name");
  c.params = in.str(kMaxParamsText, "parameters");
  c.time = in.f64("time");
  c.steps = in.uint(8, "step count");
  const std::size_t count = std::size_t(in.uint(4, "entry count"));
  if (count > kMaxEntries)
    throw Error(where + ": " + std::to_string(count) + " entries, more than the limit " + std::to_string(kMaxEntries));
  std::set<std::string> names;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = "entry " + std::to_string(i);
    const std::size_t kindAt = in.offset();
    const auto kind = EntryKind(in.uint(1, at + " kind"));
    if (kind != EntryKind::Value && kind != EntryKind::Text && kind != EntryKind::Buffer)
      throw Error(where + ": " + at + " kind at byte " + std::to_string(kindAt) + ": " + std::to_string(int(kind)) +
                  " is not 1 (value), 2 (text) or 3 (buffer)");
    std::string name = in.str(kMaxEntryName, at + " name");
    if (!names.insert(name).second) in.fail(at, "a second entry named '" + printable(name) + "'");
    const std::string field = "entry '" + printable(name) + "' (" + kindName(kind) + ")";
    const std::uint64_t n = in.uint(8, field + " size");
    in.need(n, field);
    c.entries.push_back({kind, std::move(name), in.blob(std::size_t(n))});
  }
  if (in.left() != 0) in.fail("end of entries", std::to_string(in.left()) + " bytes left over");
  return c;
}

Checkpoint readCheckpointFile(const std::filesystem::path& file) {
  const std::string where = shownPath(file);
  // O_NONBLOCK: opening a pipe does not wait for a writer; fstat then refuses it.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) throw Error("checkpoint not found: '" + where + "'");
    throw Error("cannot read checkpoint '" + where + "': " + systemError());
  }
  const struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw Error("cannot read checkpoint '" + where + "': " + systemError());
  if (S_ISDIR(st.st_mode)) throw Error("'" + where + "' is a folder, not a checkpoint file");
  if (!S_ISREG(st.st_mode))
    throw Error("'" + where + "' is not a regular file (a device, pipe or socket): give a checkpoint file");
  const std::uint64_t size = std::uint64_t(st.st_size);
  std::vector<std::uint8_t> bytes(std::min<std::uint64_t>(size, kCheckpointHeaderBytes));
  readAll(fd, bytes.data(), bytes.size(), 0, where);
  const Header header = checkHeader(bytes, size, where);  // before anything is allocated for the payload
  if (size > kMaxCheckpointFileBytes)
    throw Error("'" + where + "' is " + byteSize(size) + ", larger than the " + byteSize(kMaxCheckpointFileBytes) +
                " allowed for a checkpoint");
  try {
    bytes.resize(std::size_t(kCheckpointHeaderBytes + header.payloadBytes));
  } catch (const std::bad_alloc&) {
    throw Error("'" + where + "': not enough memory to read its " + byteSize(size));
  }
  readAll(fd, bytes.data() + kCheckpointHeaderBytes, bytes.size() - kCheckpointHeaderBytes, kCheckpointHeaderBytes,
          where);
  return parseCheckpoint(bytes, where);
}

std::filesystem::path checkpointTarget(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(file, ec);
  if (!fs::exists(link)) return file;  // a new name
  const auto refuse = [&](const std::string& what) {
    return Error("cannot write checkpoint '" + shownPath(file) + "': " + what + "; give a regular file or a new name");
  };
  if (fs::is_symlink(link)) {
    const fs::path target = fs::canonical(file, ec);
    if (ec) throw refuse("a symbolic link to nothing (" + ec.message() + ")");
    const fs::file_status st = fs::status(target, ec);
    if (!fs::is_regular_file(st))
      throw refuse(std::string("a symbolic link to ") +
                   (fs::is_directory(st) ? "a folder" : "a device, pipe or socket"));
    return target;  // written through the link, which stays
  }
  if (fs::is_directory(link)) throw refuse("it is a folder");
  if (!fs::is_regular_file(link)) throw refuse("it is a device, pipe or socket");
  return file;
}

std::filesystem::path temporaryPath(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  return tmp;
}

void writeFileAtomically(const std::filesystem::path& given, std::span<const std::uint8_t> bytes,
                         const std::function<void(WriteStep)>& crashPoint) {
  const std::filesystem::path file = checkpointTarget(given);
  const std::filesystem::path tmp = temporaryPath(file);
  const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  // A stale temporary file is replaced; a link or a pipe by that name is not followed or waited on.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd < 0) throw Error("cannot write checkpoint '" + shownPath(tmp) + "': " + systemError());
  if (struct stat st{}; ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error("cannot write checkpoint '" + shownPath(tmp) + "': not a regular file (remove it)");
  }
  try {
    const std::size_t half = bytes.size() / 2;
    writeAll(fd, bytes.data(), half, tmp);
    if (crashPoint) crashPoint(WriteStep::HalfWritten);
    writeAll(fd, bytes.data() + half, bytes.size() - half, tmp);
    if (::fsync(fd) != 0) throw Error("cannot write checkpoint '" + shownPath(tmp) + "': fsync: " + systemError());
  } catch (...) {
    ::close(fd);
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
  if (::close(fd) != 0) throw Error("cannot write checkpoint '" + shownPath(tmp) + "': " + systemError());
  if (crashPoint) crashPoint(WriteStep::BeforeRename);
  if (::rename(tmp.c_str(), file.c_str()) != 0) {
    const std::string why = systemError();
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw Error("cannot write checkpoint '" + shownPath(file) + "': rename: " + why);
  }
  // The rename is durable once the folder's entry is on disk.
  if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace tidepool::io
