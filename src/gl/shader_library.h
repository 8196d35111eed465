// Loads programs from the shaders/ folder, assembling sources (see shader_source.h), compiling,
// linking and caching them by (files, defines). On failure it throws GlError whose first line
// names the original file and line; the full mapped driver log follows on later lines.
//
//   ShaderLibrary lib(ShaderLibrary::findRoot());
//   gl::Program& scan = lib.program({"grid/scan.comp"}, {{"WG", "256"}});
//
// Programs live as long as the library, at a stable address; reload() recompiles all of them
// and keeps the old GL program wherever the new one fails. A program built for a gl::Kernel
// (gl/kernel.h) carries its KernelInterface, checked at build and on every reload.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/kernel_check.h"
#include "gl/program.h"
#include "gl/shader_source.h"

namespace tidepool::gl {

class ShaderLibrary {
 public:
  // Shader folder, first that exists: $TIDEPOOL_SHADER_DIR (must be readable, else Error),
  // <executable dir>/shaders, <executable dir>/../shaders, the source tree's shaders/.
  static std::filesystem::path findRoot();

  explicit ShaderLibrary(std::filesystem::path root);
  const std::filesystem::path& root() const { return m_root; }

  Program& program(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines = {});
  // The same, checked against `kernel` now and on every reload (gl/kernel_check.h).
  Program& program(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines,
                   const KernelInterface& kernel);

  struct ReloadResult {
    int reloaded = 0;                 // programs rebuilt and swapped in
    std::vector<std::string> errors;  // one message per program that failed (old one kept)
  };
  ReloadResult reload();
  std::size_t size() const { return m_programs.size(); }

  // Compiles, links and checks against `kernels` without caching (used by program() and
  // reload(), and by tests).
  Program build(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines,
                const std::vector<KernelInterface>& kernels = {}) const;

 private:
  struct Entry {
    std::vector<std::string> files;
    std::vector<ShaderDefine> defines;
    std::unique_ptr<Program> program;
    std::vector<KernelInterface> kernels;  // checked on reload
  };
  std::filesystem::path m_root;
  std::map<std::string, Entry> m_programs;  // key: files + defines

  ShaderFileReader reader() const;  // files under m_root
};

// Label used in messages: "grid/scan.comp [WG=256]".
std::string programLabel(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines);

}  // namespace tidepool::gl
