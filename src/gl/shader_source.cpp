#include "gl/shader_source.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace tidepool::gl {
namespace {

struct Assembler {
  const ShaderFileReader& read;
  AssembledShader out;
  std::vector<std::string> stack;  // include chain, for cycle detection

  int fileIndex(const std::string& path) {
    auto it = std::find(out.files.begin(), out.files.end(), path);
    if (it != out.files.end()) return int(it - out.files.begin());
    out.files.push_back(path);
    return int(out.files.size()) - 1;
  }

  // Parses `#include "x"`; returns nullopt when the line is not an include directive.
  static std::optional<std::string> includeTarget(const std::string& line, const std::string& where) {
    static const std::regex directive(R"(^\s*#\s*include\b(.*)$)");
    static const std::regex quoted(R"re(^\s*"([^"]+)"\s*(//.*)?$)re");
    std::smatch m;
    if (!std::regex_match(line, m, directive)) return std::nullopt;
    const std::string rest = m[1];
    std::smatch q;
    if (!std::regex_match(rest, q, quoted))
      throw Error(where + ": malformed #include, expected #include \"dir/file.glsl\"");
    return q[1].str();
  }

  static bool isVersion(const std::string& line) {
    static const std::regex version(R"(^\s*#\s*version\b.*)");
    return std::regex_match(line, version);
  }

  void emit(const std::string& line, int file, int lineNo) {
    out.text += line;
    out.text += '\n';
    out.lines.push_back({file, lineNo});
  }

  void paste(const std::string& path, const std::string& text, bool isRoot, std::span<const ShaderDefine> defines) {
    const int index = fileIndex(path);
    stack.push_back(path);
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    bool sawVersion = false;
    while (std::getline(in, line)) {
      ++lineNo;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const std::string where = path + ":" + std::to_string(lineNo);
      if (isVersion(line)) {
        if (!isRoot) throw Error(where + ": #version is only allowed in the top-level shader, not in an included file");
        if (sawVersion) throw Error(where + ": second #version line");
        sawVersion = true;
        emit(line, index, lineNo);
        for (const ShaderDefine& d : defines) emit("#define " + d.name + " " + d.value, index, lineNo);
        continue;
      }
      if (isRoot && !sawVersion) {
        const std::size_t first = line.find_first_not_of(" \t");
        const bool blankOrComment = first == std::string::npos || line.compare(first, 2, "//") == 0;
        if (!blankOrComment) throw Error(where + ": expected '#version 430 core' before any code");
      }
      if (auto target = includeTarget(line, where)) {
        if (std::find(stack.begin(), stack.end(), *target) != stack.end()) {
          std::string chain;
          for (const std::string& s : stack) chain += s + " -> ";
          throw Error(where + ": include cycle: " + chain + *target);
        }
        if (std::find(out.files.begin(), out.files.end(), *target) == out.files.end()) {
          std::optional<std::string> body = read(*target);
          if (!body) throw Error(where + ": cannot include \"" + *target + "\": no such file in the shader directory");
          paste(*target, *body, false, {});
        }
        // An included file is pasted once per program (automatic include guard).
        continue;
      }
      emit(line, index, lineNo);
    }
    if (isRoot && !sawVersion) throw Error(path + ":1: missing '#version 430 core' line");
    stack.pop_back();
  }
};

}  // namespace

AssembledShader assembleShader(const std::string& rootPath, const ShaderFileReader& read,
                               std::span<const ShaderDefine> defines) {
  std::optional<std::string> text = read(rootPath);
  if (!text) throw Error("shader '" + rootPath + "' not found in the shader directory");
  Assembler a{read, {}, {}};
  a.paste(rootPath, *text, true, defines);
  return std::move(a.out);
}

std::string mapShaderLog(const std::string& log, const AssembledShader& source) {
  // Mesa: "0:12(3): error: ..."  NVIDIA: "0(12) : error C1008: ..."  AMD/Intel: "ERROR: 0:12: ..."
  static const std::regex mesa(R"(^(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  static const std::regex khronos(R"(^(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
  auto where = [&](const std::string& lineText) {
    const std::size_t k = std::stoul(lineText);
    if (k == 0 || k > source.lines.size()) return "<assembled line " + lineText + ">";
    const SourceLine& s = source.lines[k - 1];
    return source.files[std::size_t(s.file)] + ":" + std::to_string(s.line);
  };
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia))
      out += where(m[2]) + ": " + m[3].str() + "\n";
    else if (std::regex_match(line, m, khronos))
      out += where(m[3]) + ": " + (m[1] == "ERROR" ? "error: " : "warning: ") + m[4].str() + "\n";
    else if (!line.empty())
      out += line + "\n";
  }
  return out;
}

std::string firstLogLocation(const std::string& mappedLog) {
  static const std::regex loc(R"(^([^\s:]+):(\d+): *(error|ERROR).*$)");
  std::istringstream in(mappedLog);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, loc)) return m[1].str() + ":" + m[2].str();
  }
  return "";
}

}  // namespace tidepool::gl
