# cosmems_unity_sources(<target> <unit> <sources>...): adds the sources to the target as one
# translation unit, <unit>_unity.cpp in the binary directory, which includes each source by its
# path from the current source directory (put on the target's include path).
#
# Sources that instantiate the same models, solvers and analyses compile together in a fraction
# of their CPU time apart (the CLI's reports: 207 s against 793 s in Release with GCC 12): the
# instantiations dominate, not the code. CMake's UNITY_BUILD is not used: it writes absolute
# paths into the unit, so its text, and with it ccache's key, would change with the clone's
# folder, and CI, which builds a fresh clone, would compile every unit again. The sources of one
# unit share a namespace scope: names in their anonymous namespaces must differ.
function(cosmems_unity_sources target unit)
  set(content "")
  foreach(source IN LISTS ARGN)
    get_filename_component(source ${source} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    file(RELATIVE_PATH source ${CMAKE_CURRENT_SOURCE_DIR} ${source})
    string(APPEND content "#include \"${source}\"\n")
  endforeach()
  set(file ${CMAKE_CURRENT_BINARY_DIR}/${unit}_unity.cpp)
  file(CONFIGURE OUTPUT ${file} CONTENT "${content}" @ONLY)
  target_sources(${target} PRIVATE ${file})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
endfunction()
