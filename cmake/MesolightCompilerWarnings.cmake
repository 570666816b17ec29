# Warning flags for Mesolight's own targets (VTK's headers are system headers).
function (mesolight_target_warnings target)
  if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
    if (MESOLIGHT_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif ()
  endif ()
endfunction ()
