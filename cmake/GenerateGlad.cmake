# Generates the GL loader (glad 2, C) from the Khronos spec shipped with Debian's python3-glad.
# Programs include <glad/gl.h>; each backend fills the table with its own getProcAddress.
find_program(MYGL_SYSTEM_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
execute_process(COMMAND ${MYGL_SYSTEM_PYTHON} -c "import glad"
  RESULT_VARIABLE glad_missing OUTPUT_QUIET ERROR_QUIET)
if(glad_missing)
  message(FATAL_ERROR "python3-glad is required (apt-get install python3-glad)")
endif()

set(MYGL_GLAD_DIR ${CMAKE_CURRENT_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${MYGL_GLAD_DIR}/src/gl.c ${MYGL_GLAD_DIR}/include/glad/gl.h
         ${MYGL_GLAD_DIR}/include/KHR/khrplatform.h
  COMMAND ${MYGL_SYSTEM_PYTHON} -m glad --quiet --reproducible
          --api gl:compatibility=1.1 --extensions "" --out-path ${MYGL_GLAD_DIR} c
  COMMENT "Generating the GL 1.1 loader with glad"
  VERBATIM)

add_library(mygl_loader STATIC ${MYGL_GLAD_DIR}/src/gl.c)
add_library(mygl::loader ALIAS mygl_loader)
set_target_properties(mygl_loader PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_include_directories(mygl_loader PUBLIC
  $<BUILD_INTERFACE:${MYGL_GLAD_DIR}/include>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
install(TARGETS mygl_loader EXPORT myglTargets)
install(DIRECTORY ${MYGL_GLAD_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
