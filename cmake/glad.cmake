# Generates the glad GL 4.5 core + EGL 1.5 loader into the build tree at configure time (never committed).
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
set(GLAD_STAMP ${GLAD_DIR}/.generated-gl45-egl15)
if(NOT EXISTS ${GLAD_STAMP})
  message(STATUS "Generating glad loader (gl:core=4.5, egl=1.5)")
  execute_process(
    COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5,egl=1.5 --out-path ${GLAD_DIR} c --loader
    RESULT_VARIABLE _glad_result
    OUTPUT_QUIET)
  if(NOT _glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed to generate the loader (exit ${_glad_result})")
  endif()
  file(TOUCH ${GLAD_STAMP})
endif()

add_library(glad STATIC ${GLAD_DIR}/src/gl.c ${GLAD_DIR}/src/egl.c)
target_include_directories(glad SYSTEM PUBLIC ${GLAD_DIR}/include)
target_link_libraries(glad PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
