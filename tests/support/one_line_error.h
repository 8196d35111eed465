// Bad input gets one clear line naming what is wrong and a non-zero exit, never a crash: the
// check the command-line tests make of every refusal.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/run_process.h"

namespace tidepool::test {

// Runs tidepool with `args` (and `env`); expects exit status `code`, no crash, and a single
// stderr line containing `expected`. Returns the run for further checks.
inline ProcessResult expectOneLineError(const std::vector<std::string>& args, const std::string& expected, int code = 1,
                                        const std::vector<std::string>& env = {}) {
  std::string command = "tidepool";
  for (const std::string& a : args) command += " " + a;
  const ProcessResult r = runTidepool(args, env);
  EXPECT_FALSE(r.signaled) << command << " crashed: " << r.err;
  EXPECT_EQ(r.exitCode, code) << command << "\n" << r.err;
  const std::vector<std::string> lines = r.errLines();
  EXPECT_EQ(lines.size(), 1u) << command << ": expected one line, got:\n" << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << command << "\n" << r.err;
  return r;
}

// Renders `scene` (a file in `dir`) headless and expects it to end like a failed run: no crash,
// exit status 1, and a last stderr line (after any progress) containing `expected`. Returns
// that line.
inline std::string expectRenderFails(const std::string& scene, const std::string& outDir, const std::string& expected) {
  const ProcessResult r = runTidepool({"render", scene, "--out", outDir, "--quiet"});
  EXPECT_FALSE(r.signaled) << r.err;
  EXPECT_EQ(r.exitCode, 1) << r.err;
  const std::vector<std::string> lines = r.errLines();
  const std::string last = lines.empty() ? "" : lines.back();
  EXPECT_NE(last.find(expected), std::string::npos) << r.err;
  return last;
}

}  // namespace tidepool::test
