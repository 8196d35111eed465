// Writing an output file so that a reader, or a run killed midway, never sees half of it: the
// bytes go to "<file>.tmp" in the same folder, which is then renamed over the file. (Not fsynced:
// exports are replaceable, unlike checkpoints, which io/checkpoint_file.h also makes durable.)
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace tidepool::io {

// Throws Error "cannot write '<file>': <the system's reason>" (a missing folder, a full disk, a
// file-size limit); the temporary file is removed then.
void replaceFile(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);

}  // namespace tidepool::io
