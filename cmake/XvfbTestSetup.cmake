# Shared start of the window tests (cmake -P scripts): skip (exit 77) where xvfb-run is missing,
# else give XVFB_RUN and an empty ${OUT}.
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message("xvfb-run not found: skipped")
  cmake_language(EXIT 77)
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
