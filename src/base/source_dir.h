// Where this build's source tree lives (shaders/, assets/, bench/): the last place the program
// looks for its data when nothing sits next to the executable. Only source_dir.cpp sees the
// path, so moving a checkout recompiles one file.
#pragma once

#include <filesystem>

namespace tidepool {

std::filesystem::path sourceDir();

}  // namespace tidepool
