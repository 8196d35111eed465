# Generates the GL 4.3 core + EGL 1.5 loader with glad (python3-glad) at build time.
# The generated files live in the build folder only; they are never committed.
find_program(GLAD_EXECUTABLE glad REQUIRED)

set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
# Only the extensions we use. GL 4.3 core already includes KHR_debug and compute shaders;
# the memory-info extensions are optional paths detected at run time.
set(GLAD_GL_EXTENSIONS GL_NVX_gpu_memory_info GL_ATI_meminfo)
set(GLAD_EGL_EXTENSIONS
    EGL_EXT_platform_base EGL_EXT_platform_device EGL_EXT_device_base EGL_EXT_device_enumeration
    EGL_EXT_device_query EGL_MESA_platform_surfaceless EGL_KHR_surfaceless_context
    EGL_KHR_create_context EGL_KHR_no_config_context)
list(JOIN GLAD_GL_EXTENSIONS "," _gl_ext)
list(JOIN GLAD_EGL_EXTENSIONS "," _egl_ext)

set(GLAD_SOURCES ${GLAD_OUT}/src/gl.c ${GLAD_OUT}/src/egl.c)
add_custom_command(
  OUTPUT ${GLAD_SOURCES} ${GLAD_OUT}/include/glad/gl.h ${GLAD_OUT}/include/glad/egl.h
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${GLAD_OUT}
  COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.3,egl=1.5
          --extensions ${_gl_ext},${_egl_ext} --out-path ${GLAD_OUT} c --loader
  COMMENT "Generating the GL 4.3 core / EGL 1.5 loader with glad"
  VERBATIM)

add_library(glad STATIC ${GLAD_SOURCES})
target_include_directories(glad SYSTEM PUBLIC ${GLAD_OUT}/include)
target_link_libraries(glad PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
