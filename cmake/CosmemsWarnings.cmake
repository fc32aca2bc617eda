# Warnings (and -Werror when COSMEMS_WARNINGS_AS_ERRORS) for cosmems' own targets only: they are
# PRIVATE, so nothing here reaches a consumer of the installed package.
function(cosmems_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion)
  if(COSMEMS_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
