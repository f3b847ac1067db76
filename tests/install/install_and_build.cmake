# Installs the project into a scratch prefix and builds a consumer project against it with
# find_package(mygl), then optionally runs one of its programs:
#   cmake -DBUILD=<build dir> -DPREFIX=<prefix> -DSOURCE=<consumer source> -DCONSUMER_BUILD=<dir>
#         [-DCONFIGURE_ARGS=-DA=1|-DB=2] [-DRUN=<program in the consumer build>] -P install_and_build.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "step failed (${result}): ${ARGN}")
  endif()
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})
string(REPLACE "|" ";" configure_args "${CONFIGURE_ARGS}")
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX})
run(${CMAKE_COMMAND} -S ${SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX} ${configure_args})
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD} -j2)
if(RUN)
  run(${CONSUMER_BUILD}/${RUN})
endif()
