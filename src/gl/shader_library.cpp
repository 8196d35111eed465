#include "gl/shader_library.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "base/source_dir.h"
#include "io/echo.h"

namespace tidepool::gl {
namespace fs = std::filesystem;

namespace {

GLenum stageOf(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".comp") return GL_COMPUTE_SHADER;
  if (ext == ".vert") return GL_VERTEX_SHADER;
  if (ext == ".frag") return GL_FRAGMENT_SHADER;
  if (ext == ".geom") return GL_GEOMETRY_SHADER;
  throw GlError("shader '" + path + "': unknown stage, expected .comp, .vert, .frag or .geom");
}

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  if (isProgram)
    glGetProgramInfoLog(object, length, nullptr, log.data());
  else
    glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  return log;
}

fs::path executableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

}  // namespace

std::string programLabel(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines) {
  std::string label;
  for (const std::string& f : files) label += (label.empty() ? "" : " + ") + f;
  if (!defines.empty()) {
    label += " [";
    for (std::size_t i = 0; i < defines.size(); ++i)
      label += (i ? ", " : "") + defines[i].name + (defines[i].value.empty() ? "" : "=" + defines[i].value);
    label += "]";
  }
  return label;
}

fs::path ShaderLibrary::findRoot() {
  if (const char* env = std::getenv("TIDEPOOL_SHADER_DIR")) {
    const fs::path dir(env);
    std::error_code ec;
    if (!fs::is_directory(dir, ec) || access(dir.c_str(), R_OK | X_OK) != 0)
      throw Error("shader directory '" + io::shownPath(dir) +
                  "' (from TIDEPOOL_SHADER_DIR) is not a readable directory");
    return dir;
  }
  const fs::path exeDir = executableDir();
  for (const fs::path& candidate : {exeDir / "shaders", exeDir / ".." / "shaders", sourceDir() / "shaders"}) {
    std::error_code ec;
    if (fs::is_regular_file(candidate / "common" / "index.glsl", ec)) return fs::weakly_canonical(candidate);
  }
  throw Error("shader directory not found next to the executable or in the source tree; set TIDEPOOL_SHADER_DIR");
}

ShaderLibrary::ShaderLibrary(fs::path root) : m_root(std::move(root)) {
  std::error_code ec;
  if (!fs::is_directory(m_root, ec) || access(m_root.c_str(), R_OK | X_OK) != 0)
    throw Error("shader directory '" + io::shownPath(m_root) + "' is not a readable directory");
}

ShaderFileReader ShaderLibrary::reader() const {
  return [this](const std::string& path) -> std::optional<std::string> {
    std::ifstream in(m_root / path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
}

Program ShaderLibrary::build(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines,
                             const std::vector<KernelInterface>& kernels) const {
  const std::string label = programLabel(files, defines);
  std::vector<Handle<Kind::Shader>> shaders;
  std::string source;  // all stages' assembled text, for the kernel checks
  for (const std::string& file : files) {
    const GLenum stage = stageOf(file);
    AssembledShader src = assembleShader(file, reader(), defines);
    source += src.text;
    Handle<Kind::Shader> shader(glCreateShader(stage));
    const char* text = src.text.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = mapShaderLog(infoLog(shader.get(), false), src);
      const std::string where = firstLogLocation(log);
      throw GlError("shader '" + label + "' failed to compile" + (where.empty() ? "" : " at " + where) + "\n" + log);
    }
    shaders.push_back(std::move(shader));
  }
  Handle<Kind::Program> program(glCreateProgram());
  for (const auto& s : shaders) glAttachShader(program.get(), s.get());
  glLinkProgram(program.get());
  for (const auto& s : shaders) glDetachShader(program.get(), s.get());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) throw GlError("program '" + label + "' failed to link\n" + infoLog(program.get(), true));
  Program result(std::move(program), label);
  for (const KernelInterface& kernel : kernels) checkKernel(result, source, kernel);
  return result;
}

Program& ShaderLibrary::program(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines) {
  const std::string key = programLabel(files, defines);
  auto it = m_programs.find(key);
  if (it != m_programs.end()) return *it->second.program;
  auto built = std::make_unique<Program>(build(files, defines));
  Program& ref = *built;
  m_programs.emplace(key, Entry{files, defines, std::move(built), {}});
  return ref;
}

Program& ShaderLibrary::program(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines,
                                const KernelInterface& kernel) {
  const std::string key = programLabel(files, defines);
  auto it = m_programs.find(key);
  if (it == m_programs.end()) {
    auto built = std::make_unique<Program>(build(files, defines, {kernel}));
    it = m_programs.emplace(key, Entry{files, defines, std::move(built), {kernel}}).first;
  } else if (std::find(it->second.kernels.begin(), it->second.kernels.end(), kernel) == it->second.kernels.end()) {
    std::string source;
    for (const std::string& file : files) source += assembleShader(file, reader(), defines).text;
    checkKernel(*it->second.program, source, kernel);
    it->second.kernels.push_back(kernel);
  }
  return *it->second.program;
}

ShaderLibrary::ReloadResult ShaderLibrary::reload() {
  ReloadResult result;
  for (auto& [key, entry] : m_programs) {
    try {
      Program fresh = build(entry.files, entry.defines, entry.kernels);
      entry.program->swap(fresh);
      ++result.reloaded;
    } catch (const Error& e) {
      result.errors.emplace_back(e.what());
    }
  }
  return result;
}

}  // namespace tidepool::gl
