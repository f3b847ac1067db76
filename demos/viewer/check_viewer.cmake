# cmake -DVIEWER=... -DDEMO=... -DCOMPARE=... -DOUT=<dir> -P check_viewer.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/XvfbTestSetup.cmake)
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24" ${VIEWER} --scene cube --exact --screenshot ${OUT}/window.png
                RESULT_VARIABLE result TIMEOUT 60)
if(NOT result EQUAL 0 OR NOT EXISTS ${OUT}/window.png)
  message(FATAL_ERROR "the viewer did not run under Xvfb: ${result}")
endif()
execute_process(COMMAND ${DEMO} --scene cube --backend mygl --size 640x480 --out ${OUT} RESULT_VARIABLE result)
execute_process(COMMAND ${COMPARE} ${OUT}/window.png ${OUT}/cube-mygl.png --tolerance 0
                RESULT_VARIABLE result OUTPUT_VARIABLE numbers)
message("window against the scene rendered headless: ${numbers}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the viewer's window does not show the scene")
endif()
