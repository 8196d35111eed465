// Runs the tidepool executable (or any command) and captures its exit status and output.
#pragma once

#include <string>
#include <vector>

namespace tidepool::test {

struct ProcessResult {
  int exitCode = -1;      // valid when exited normally
  bool signaled = false;  // killed by a signal (a crash)
  std::string out, err;
  std::vector<std::string> errLines() const;
};

// Arguments are passed without a shell. `env` entries "NAME=value" are added to the environment.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});
ProcessResult runTidepool(const std::vector<std::string>& args, const std::vector<std::string>& env = {});

}  // namespace tidepool::test
