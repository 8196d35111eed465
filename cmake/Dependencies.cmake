# Every dependency comes from a Debian 12 package (scripts/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(glfw3 3.3 REQUIRED)                 # libglfw3-dev
find_package(glm REQUIRED)                       # libglm-dev
find_package(nlohmann_json 3.10 REQUIRED)        # nlohmann-json3-dev
find_package(CLI11 REQUIRED)                     # libcli11-dev
find_package(Threads REQUIRED)
pkg_check_modules(IMGUI REQUIRED imgui)          # libimgui-dev (static, GLFW + OpenGL3 backends)
# imgui.pc also names libstb; io/stb_impl.cpp already defines stb (the io layer follows imgui on the
# link line), so tidepool links the static libimgui alone and needs no libstb.so at run time.
find_library(IMGUI_STATIC_LIBRARY imgui HINTS ${IMGUI_LIBRARY_DIRS} REQUIRED)
add_library(imgui_static INTERFACE)
target_include_directories(imgui_static SYSTEM INTERFACE ${IMGUI_INCLUDE_DIRS})
target_link_libraries(imgui_static INTERFACE ${IMGUI_STATIC_LIBRARY})
pkg_check_modules(EGL REQUIRED egl)              # libegl-dev: headers checked; the loader is dlopen'ed by glad
pkg_check_modules(OSMESA REQUIRED osmesa)        # libosmesa6-dev: header only; libOSMesa is dlopen'ed at run time
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)  # libstb-dev (headers)
if(TIDEPOOL_BUILD_TESTS)
  find_package(GTest REQUIRED)                   # libgtest-dev
endif()
