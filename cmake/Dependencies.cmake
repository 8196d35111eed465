# Every dependency comes from a Debian 12 package (scripts/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(glfw3 3.3 REQUIRED)                 # libglfw3-dev
find_package(glm REQUIRED)                       # libglm-dev
find_package(nlohmann_json 3.10 REQUIRED)        # nlohmann-json3-dev
find_package(CLI11 REQUIRED)                     # libcli11-dev
find_package(Threads REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)  # libimgui-dev (static, GLFW + OpenGL3 backends)
pkg_check_modules(EGL REQUIRED egl)              # libegl-dev: headers checked; the loader is dlopen'ed by glad
pkg_check_modules(OSMESA REQUIRED osmesa)        # libosmesa6-dev: header only; libOSMesa is dlopen'ed at run time
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)  # libstb-dev (headers)
if(TIDEPOOL_BUILD_TESTS)
  find_package(GTest REQUIRED)                   # libgtest-dev
endif()
