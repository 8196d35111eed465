# Builds each probe target of tests/layers alone and checks the outcome.
#   EXPECT=build: every target compiles.
#   EXPECT=fail:  every target fails, and its compiler output names the header it may not see
#                 (HEADERS[i] for TARGETS[i]), so that an unrelated error can't pass the test.
list(LENGTH TARGETS count)
math(EXPR last "${count} - 1")
set(failures "")
foreach(i RANGE ${last})
  list(GET TARGETS ${i} target)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${target}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(EXPECT STREQUAL "build")
    if(NOT result EQUAL 0)
      string(APPEND failures "${target} did not build:\n${out}${err}\n")
    endif()
  else()
    list(GET HEADERS ${i} header)
    string(FIND "${out}${err}" "${header}: No such file" named)
    if(result EQUAL 0)
      string(APPEND failures "${target} built: an upward include of ${header} was allowed\n")
    elseif(named EQUAL -1)
      string(APPEND failures "${target} failed for another reason than ${header}:\n${out}${err}\n")
    endif()
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
message(STATUS "${count} probes: ${EXPECT} as expected")
