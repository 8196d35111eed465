// What every fuzz target checks: an input either parses, or is refused by one tidepool::Error
// whose message is one line starting with the input's name (the file, then the place). Any
// other exception, a crash, a leak or undefined behaviour is a finding (libFuzzer stops on
// std::abort, and ASan/UBSan on the rest).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/error.h"

namespace tidepool::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

// Runs parse(); a tidepool::Error must be one line that starts with `name`.
template <class Parse>
void expectParsedOrRefused(const std::string& name, Parse&& parse) {
  try {
    parse();
  } catch (const Error& e) {
    const std::string m = e.what();
    if (m.find('\n') != std::string::npos || m.find('\r') != std::string::npos)
      finding("error message is not one line: " + m);
    if (m.rfind(name, 0) != 0) finding("error message does not start with '" + name + "': " + m);
    if (m.size() > 4096) finding("error message of " + std::to_string(m.size()) + " characters: " + m.substr(0, 200));
  }
}

}  // namespace tidepool::fuzz
