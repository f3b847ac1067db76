# Warning and sanitizer flags shared by every target of the project.
add_library(mygl_build_flags INTERFACE)
target_compile_options(mygl_build_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion $<$<BOOL:${MYGL_WERROR}>:-Werror>)
if(MYGL_SANITIZE)
  target_compile_options(mygl_build_flags INTERFACE -fsanitize=address,undefined
    -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(mygl_build_flags INTERFACE -fsanitize=address,undefined)
endif()
if(MYGL_CHECK_INVARIANTS)
  target_compile_definitions(mygl_build_flags INTERFACE MYGL_CHECK_INVARIANTS _GLIBCXX_ASSERTIONS)
endif()
# The reference's arithmetic is reproduced operation by operation; the compiler must not fuse
# a*b+c into one rounding where the reference does two (or the other way round).
target_compile_options(mygl_build_flags INTERFACE -ffp-contract=off)
