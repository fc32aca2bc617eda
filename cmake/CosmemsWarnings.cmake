# Warnings (and -Werror when COSMEMS_WARNINGS_AS_ERRORS) for cosmems' own targets only: they are
# PRIVATE, so nothing here reaches a consumer of the installed package. -Wnull-dereference is
# left out: GCC 12 raises it at -O2 and above inside Eigen's inlined kernels (zero-size vectors
# have null data pointers on paths never taken), which -Werror would turn into broken builds.
function(cosmems_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wcast-align -Wunused -Woverloaded-virtual -Wdouble-promotion)
  if(COSMEMS_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
