// GLSL source assembly on the CPU (no GL calls, so it is unit-tested without a context):
//   #version line, injected #defines, `#include "common/x.glsl"` resolved against the shader
//   root with automatic include guards (a file is pasted once per program) and cycle detection,
//   and a line table so that compile logs map back to the original files.
//
//   root file  grid/scan.comp           assembled text                 line table
//   ------------------------------      ---------------------------    ------------------------
//   #version 430 core                   #version 430 core              grid/scan.comp:1
//   layout(local_size_x = WG) in;       #define WG 256                 (injected) -> :1
//   #include "common/index.glsl"   ->   layout(local_size_x = WG) in;  grid/scan.comp:2
//   void main() { ... }                 ...lines of index.glsl...      common/index.glsl:1..n
//                                       void main() { ... }            grid/scan.comp:4
//
// Drivers disagree on `#line` source numbers (Mesa reports some errors against the wrong
// one), so no #line directives are emitted: the line table maps assembled lines instead.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/error.h"

namespace tidepool::gl {

struct ShaderDefine {
  std::string name;
  std::string value;
};

struct SourceLine {
  int file;  // index into AssembledShader::files
  int line;  // 1-based line in that file
};

struct AssembledShader {
  std::string text;                // ready for glShaderSource
  std::vector<std::string> files;  // paths relative to the shader root; [0] is the root file
  std::vector<SourceLine> lines;   // origin of each assembled line (lines[k - 1] for line k)
};

// Reads a file by its path relative to the shader root; nullopt when it does not exist.
using ShaderFileReader = std::function<std::optional<std::string>(const std::string& path)>;

// Throws Error naming file and line for: a missing #version, a missing include, an include
// cycle (with the chain), a #version inside an included file, a malformed #include line.
AssembledShader assembleShader(const std::string& rootPath, const ShaderFileReader& read,
                               std::span<const ShaderDefine> defines = {});

// Rewrites driver log prefixes ("0:12(3): error" Mesa, "0(12) : error" NVIDIA,
// "ERROR: 0:12:" AMD/Intel) into "path:line: error" using the line table.
std::string mapShaderLog(const std::string& log, const AssembledShader& source);

// First "path:line" found in a mapped log, for one-line error messages ("" when none).
std::string firstLogLocation(const std::string& mappedLog);

}  // namespace tidepool::gl
