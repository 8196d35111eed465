#include "support/readme_commands.h"

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

namespace tidepool::test {

ReadmeRules readmeRules() {
  ReadmeRules r;
  // Every subcommand takes a balls scene, so one name stands for any scene.
  r.scene = "dam-break";
  r.placeholders = {"N", "K", "T", "S", "R", "WxH", "FILE", "DIR", "KEY=VALUE", "..."};
  // "`tidepool`" is the program; "`tidepool render`" names the subcommand in prose ("in `tidepool
  // render`, the benchmarks and the tests"). `tidepool run` and `tidepool info` are commands.
  r.names = {"tidepool", "tidepool render"};
  // The command table's synopses and the prose's, with placeholders a user fills in.
  r.synopses = {
      "tidepool render <scene> --frames N --size WxH [--out DIR] [--video clip.mp4]",
      "tidepool info [--backend egl\\|osmesa]",
      "tidepool bench <name> [--repeats N] [--csv FILE]",
      "tidepool sweep <study> [--quick]",
      "tidepool soak <scene> --steps N",
      "LIBGL_ALWAYS_SOFTWARE=1 tidepool ... --backend egl",
      "tidepool validate <scene> --probe energy,overlap,front,height --every K --until T --csv out.csv",
      "tidepool sweep <study>",
      "tidepool run <scene> --resume <file>",
      "tidepool bench <name>",
      "tidepool bench <name> --help",
  };
  // Out of scope here: scripts/start.sh is what CI's .ci/run runs first (it installs packages),
  // scripts/test.sh is the suite this test belongs to, and the shader-mutation pair copies the
  // shaders and runs ctest, which tests/sim/balls/contact_stability_test.cpp documents.
  r.otherTools = {"scripts/start.sh", "scripts/test.sh", "cp -r shaders /tmp/mut", "cd build && "};
  r.subcommands = {"run", "render", "info", "bench", "sweep", "validate", "soak", "check-resume"};
  return r;
}

namespace {

bool contains(const std::vector<std::string>& list, const std::string& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string joined(const std::vector<std::string>& w) {
  std::string s;
  for (const std::string& x : w) s += (s.empty() ? "" : " ") + x;
  return s;
}

bool isPlaceholder(const std::string& word, const ReadmeRules& rules) {
  return contains(rules.placeholders, word) || word.find_first_of("<>[]") != std::string::npos ||
         word.find("\\|") != std::string::npos;
}

class Reader {
 public:
  explicit Reader(const ReadmeRules& rules) : m_rules(rules) {}

  // A command as the README writes it: variables, the program (left out in the prose's shorthand), words.
  void command(int line, const std::string& text, bool fenced) {
    std::vector<std::string> w = words(text);
    ReadmeCommand c{.line = line, .text = text};
    std::size_t i = 0;
    while (i < w.size() && std::regex_match(w[i], std::regex("[A-Z_][A-Z0-9_]*=\\S*"))) c.env.push_back(w[i++]);
    if (i == w.size()) return error(line, "`" + text + "`: no program after the variables");
    const bool program = w[i] == "tidepool" || w[i] == "build/tidepool";
    if (program) ++i;
    c.args.assign(w.begin() + std::ptrdiff_t(i), w.end());
    if (!fenced && contains(m_rules.names, text)) return;
    bool placeholder = false;
    for (std::string& a : c.args) {
      if (a == "<scene>" || a == "[scene]") a = m_rules.scene;
      placeholder = placeholder || isPlaceholder(a, m_rules);
    }
    placeholder = placeholder || std::any_of(c.env.begin(), c.env.end(), [&](const std::string& e) {
                    return isPlaceholder(e.substr(e.find('=') + 1), m_rules);
                  });
    if (placeholder) {
      if (!contains(m_rules.synopses, text))
        return error(line, "`" + text +
                               "` has placeholders but is not a synopsis readmeRules() lists: list it there, or "
                               "write a command that runs");
      m_seenSynopses.insert(text);
      m_out.synopses.push_back(c);
      return;
    }
    for (const std::string& a : c.args)
      if (a.find_first_of("'\"$;&|*?()\\`") != std::string::npos)
        return error(line, "`" + text + "`: `" + a + "` needs a shell, which this test does not run");
    m_out.runnable.push_back(c);
  }

  void fencedLine(int line, const std::string& raw) {
    std::string text = raw;
    const std::size_t hash = text.find(" #");
    if (hash != std::string::npos) text.erase(hash);
    text = joined(words(text));
    if (text.empty()) return;
    if (text == "tidepool" || text.rfind("tidepool ", 0) == 0 || text.rfind("build/tidepool ", 0) == 0 ||
        text == "build/tidepool")
      return command(line, text, true);
    for (const std::string& prefix : m_rules.otherTools)
      if (text.rfind(prefix, 0) == 0) return;
    error(line, "a ```sh line that is neither a tidepool command nor in readmeRules().otherTools: `" + text + "`");
  }

  void span(int line, const std::string& raw) {
    const std::string text = joined(words(raw));  // a span may wrap onto the next line
    const std::vector<std::string> w = words(text);
    if (w.empty()) return;
    std::size_t i = 0;
    while (i + 1 < w.size() && std::regex_match(w[i], std::regex("[A-Z_][A-Z0-9_]*=\\S*"))) ++i;
    if (w[i] == "tidepool" || w[i] == "build/tidepool") return command(line, text, false);
    if (i == 0 && contains(m_rules.subcommands, w[0]) && text.find(" --") != std::string::npos)
      return command(line, text, false);
  }

  ReadmeCommands finish() {
    for (const std::string& s : m_rules.synopses)
      if (!m_seenSynopses.count(s))
        m_out.errors.push_back("README.md: the synopsis `" + s +
                               "` that readmeRules() lists is not in the README any more: remove it there");
    return std::move(m_out);
  }

 private:
  void error(int line, const std::string& why) {
    m_out.errors.push_back("README.md:" + std::to_string(line) + ": " + why);
  }

  const ReadmeRules& m_rules;
  ReadmeCommands m_out;
  std::set<std::string> m_seenSynopses;
};

}  // namespace

ReadmeCommands readReadmeCommands(const std::string& markdown, const ReadmeRules& rules) {
  Reader reader(rules);
  std::istringstream in(markdown);
  bool fenced = false, shell = false, inSpan = false;
  std::string span;  // the open `span`, which may wrap onto the next line
  int spanLine = 0, number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      shell = fenced && (line == "```sh" || line == "```bash" || line == "```shell");
      inSpan = false;
      continue;
    }
    if (fenced) {
      if (shell) reader.fencedLine(number, line);
      continue;
    }
    if (line.empty()) inSpan = false;  // a paragraph's end closes a stray backtick
    for (char ch : line)
      if (ch == '`') {
        if (inSpan) reader.span(spanLine, span);
        span.clear();
        spanLine = number;
        inSpan = !inSpan;
      } else if (inSpan) {
        span += ch;
      }
    if (inSpan) span += ' ';
  }
  return reader.finish();
}

}  // namespace tidepool::test
