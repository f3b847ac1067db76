# cmake -P install_and_build.cmake <build dir> <prefix> <consumer source> <consumer build>
set(build ${CMAKE_ARGV3})
set(prefix ${CMAKE_ARGV4})
set(source ${CMAKE_ARGV5})
set(consumer_build ${CMAKE_ARGV6})
file(REMOVE_RECURSE ${prefix} ${consumer_build})
foreach(step
    "${CMAKE_COMMAND};--install;${build};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${source};-B;${consumer_build};-DCMAKE_PREFIX_PATH=${prefix}"
    "${CMAKE_COMMAND};--build;${consumer_build}"
    "${consumer_build}/consumer")
  execute_process(COMMAND ${step} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "step failed (${result}): ${step}")
  endif()
endforeach()
