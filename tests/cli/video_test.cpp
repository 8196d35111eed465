// --video with the real ffmpeg (installed by scripts/install-deps.sh): an MP4 and a GIF of a short
// clip, checked by ffprobe (codec, size, frame count); an odd size is padded for H.264; a name
// with a quote in it is one file, not a shell command; a name starting with '-' is a file, not an
// option of ffmpeg's; an ffmpeg that ends well having written nothing is an error.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "io/video.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"
#include "support/run_process.h"

using tidepool::test::runTidepool;

namespace {

// ffprobe's "codec,width,height,frames" of the first video stream.
std::string probe(const std::filesystem::path& file) {
  const std::string cmd =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 \"" +
      file.string() + "\" 2>&1";
  std::string out;
  if (std::FILE* pipe = popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

bool ffprobeAvailable() { return std::system("ffprobe -version >/dev/null 2>&1") == 0; }

}  // namespace

TEST(Video, RealFfmpegWritesAnMp4AndAPaletteGif) {
  if (!tidepool::io::ffmpegAvailable() || !ffprobeAvailable())
    GTEST_SKIP() << "ffmpeg is not installed here (scripts/install-deps.sh installs it; CI runs this)";
  tidepool::test::TempDir dir;
  const std::filesystem::path mp4 = dir / "it's a clip.mp4", gif = dir / "clip.GIF";
  auto r =
      runTidepool({"render", "life-cells", "--frames", "6", "--size", "65x37", "--video", mp4.string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(probe(mp4), "h264,66,38,6") << "H.264 needs even sizes: 65x37 is padded to 66x38";
  r = runTidepool({"render", "life-cells", "--frames", "5", "--size", "64x36", "--video", gif.string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(probe(gif), "gif,64,36,5");
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 2u) << "the quoted name made one file, nothing else";
}

TEST(Video, NameStartingWithADashIsAFileNotAnOption) {
  if (!tidepool::io::ffmpegAvailable() || !ffprobeAvailable())
    GTEST_SKIP() << "ffmpeg is not installed here (scripts/install-deps.sh installs it; CI runs this)";
  tidepool::test::TempDir dir;
  // Relative names, from inside the folder: "-version" was once ffmpeg's option (it printed its
  // version, wrote nothing, and the run said "wrote video"); now it is a file name without a format.
  const auto render = [&](const std::string& name) {
    return tidepool::test::runProcess(
        {"sh", "-c",
         "cd '" + dir.path().string() +
             "' && exec '" TIDEPOOL_EXE "' render life-cells --frames 2 --size 32x32 --quiet --video=" + name});
  };
  auto r = render("-version");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(r.err.find("wrote video"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ffmpeg failed writing '-version'"), std::string::npos) << r.err;
  r = render("-version.mp4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(probe(dir / "-version.mp4"), "h264,32,32,2") << r.err;
}

TEST(Video, FfmpegThatWritesNothingIsAnError) {
  tidepool::test::TempDir dir;
  dir.write("bin/ffmpeg", "#!/bin/sh\ncat > /dev/null\nexit 0\n");  // reads every frame, writes no file
  std::filesystem::permissions(dir / "bin/ffmpeg", std::filesystem::perms::owner_all);
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin";
  tidepool::test::expectOneLineError(
      {"render", "life-cells", "--frames", "2", "--size", "32x32", "--video", (dir / "clip.mp4").string(), "--quiet"},
      "ffmpeg ended without writing '" + (dir / "clip.mp4").string() + "'", 1,
      {"PATH=" + (dir / "bin").string() + ":" + path});
}
