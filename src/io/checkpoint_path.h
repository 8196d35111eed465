// What a checkpoint path may be, beside the format (io/checkpoint_file.h): how large a file is
// read, and where a write goes. readCheckpointFile reads only a regular file (a pipe or a device
// is refused without waiting on it), its 24-byte header first, and refuses a stated size other
// than the file's or above kMaxCheckpointFileBytes before it allocates the payload.
#pragma once

#include <cstdint>
#include <filesystem>

namespace tidepool::io {

// The largest file read: the largest state is 2^28 - 4096 balls (the windowed-array limit) at 80 B
// each (positions, velocities, Verlet's accelerations, the watch's good copy of the first two),
// 21.5 GB.
inline constexpr std::uint64_t kMaxCheckpointFileBytes = std::uint64_t(32) << 30;

// Where a write to `file` goes: `file` itself when it is a regular file or a new name; the file a
// symbolic link points to (the write goes through, beside that file, and the link stays); a
// folder, a device, a pipe, a socket or a link to one or to nothing is refused with an Error
// naming it, before anything is written. writeFileAtomically asks it first.
std::filesystem::path checkpointTarget(const std::filesystem::path& file);

}  // namespace tidepool::io
