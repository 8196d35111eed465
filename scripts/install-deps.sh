#!/usr/bin/env bash
# Installs exactly the Debian 12 packages tidepool builds, runs and tests with (as root or via sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  # build
  build-essential cmake ninja-build pkg-config python3-glad
  # libraries (headers; imgui is a static library with the GLFW and OpenGL3 backends)
  libglfw3-dev libglm-dev libimgui-dev libegl-dev libosmesa6-dev nlohmann-json3-dev libstb-dev libcli11-dev
  libgtest-dev
  # run: Mesa (llvmpipe through EGL/GLX/OSMesa) for machines without a GPU driver of their own
  libegl-mesa0 libgl1-mesa-dri libosmesa6
  # tests: the window path runs under Xvfb (Xlib sends it key events); CI checks formatting; VTK's own reader
  # reads the exports back
  xvfb xauth libx11-dev clang-format python3-vtk9
  # charts of speed against accuracy (tidepool sweep); --video clips (MP4, GIF)
  gnuplot-nox ffmpeg
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
