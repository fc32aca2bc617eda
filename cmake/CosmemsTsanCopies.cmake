# cosmems_tsan_copies(<target>...): a copy `<lib>_tsan` of every static library of this project
# that the targets link, directly or through one another, compiled with -fsanitize=thread, for
# the ThreadSanitizer tests that drive the command line, a haptic session or the Python module
# from several threads (tests/). Both sides of every thread must be instrumented for TSan to see
# a race, so the copies replace the libraries whole. A copy follows its original's sources,
# include directories, definitions, options and links (each linked library by its copy), so a
# file added to a library is in its copy too. Made once per library; the copies made so far are
# the global property COSMEMS_TSAN_COPIES. The imported targets the libraries link (Threads,
# MPI, ...) must be found in the calling directory.

# Adds `target` and the project's static libraries it links to `out_list`.
function(_cosmems_tsan_collect target out_list)
  set(collected ${${out_list}})
  get_target_property(aliased ${target} ALIASED_TARGET)
  if(aliased)
    set(target ${aliased})
  endif()
  get_target_property(type ${target} TYPE)
  get_target_property(imported ${target} IMPORTED)
  if(NOT type STREQUAL "STATIC_LIBRARY" OR imported OR target IN_LIST collected)
    return()
  endif()
  list(APPEND collected ${target})
  get_target_property(links ${target} LINK_LIBRARIES)
  foreach(link IN LISTS links)
    if(TARGET ${link})
      _cosmems_tsan_collect(${link} collected)
    endif()
  endforeach()
  set(${out_list} ${collected} PARENT_SCOPE)
endfunction()

# `out`: the link items `items` with every copied library (by name or alias, bare or in
# $<LINK_ONLY:...>) replaced by its copy.
function(cosmems_tsan_links out items)
  get_property(copies GLOBAL PROPERTY COSMEMS_TSAN_COPIES)
  set(mapped "")
  foreach(item IN LISTS items)
    set(inner ${item})
    set(link_only FALSE)
    if(item MATCHES "^\\$<LINK_ONLY:(.+)>$")
      set(inner ${CMAKE_MATCH_1})
      set(link_only TRUE)
    endif()
    if(TARGET ${inner})
      get_target_property(aliased ${inner} ALIASED_TARGET)
      if(aliased)
        set(inner ${aliased})
      endif()
      if(inner IN_LIST copies)
        set(item ${inner}_tsan)
        if(link_only)
          set(item "$<LINK_ONLY:${inner}_tsan>")
        endif()
      endif()
    endif()
    list(APPEND mapped "${item}")
  endforeach()
  set(${out} "${mapped}" PARENT_SCOPE)
endfunction()

# `copy`, an existing target, given `target`'s sources and build properties, under
# ThreadSanitizer.
function(cosmems_tsan_copy target copy)
  get_target_property(source_dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    get_filename_component(source ${source} ABSOLUTE BASE_DIR ${source_dir})
    target_sources(${copy} PRIVATE ${source})
  endforeach()
  foreach(property INCLUDE_DIRECTORIES COMPILE_DEFINITIONS COMPILE_OPTIONS COMPILE_FEATURES
      INTERFACE_INCLUDE_DIRECTORIES INTERFACE_COMPILE_DEFINITIONS INTERFACE_COMPILE_OPTIONS
      INTERFACE_COMPILE_FEATURES)
    get_target_property(value ${target} ${property})
    if(value)
      set_property(TARGET ${copy} PROPERTY ${property} "${value}")
    endif()
  endforeach()
  foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
    get_target_property(value ${target} ${property})
    if(value)
      cosmems_tsan_links(value "${value}")
      set_property(TARGET ${copy} APPEND PROPERTY ${property} "${value}")
    endif()
  endforeach()
  # Line tables only (-g1), as the other ThreadSanitizer tests (tests/CMakeLists.txt).
  target_compile_options(${copy} PRIVATE -fsanitize=thread -O1 -g1)
  set_target_properties(${copy} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

function(cosmems_tsan_copies)
  set(libraries "")
  foreach(target IN LISTS ARGN)
    _cosmems_tsan_collect(${target} libraries)
  endforeach()
  get_property(copies GLOBAL PROPERTY COSMEMS_TSAN_COPIES)
  if(copies)
    list(REMOVE_ITEM libraries ${copies})
  endif()
  # All names first: a copy's links map to the copies of libraries made in the same call.
  set_property(GLOBAL APPEND PROPERTY COSMEMS_TSAN_COPIES ${libraries})
  foreach(target IN LISTS libraries)
    add_library(${target}_tsan STATIC)
    cosmems_tsan_copy(${target} ${target}_tsan)
  endforeach()
endfunction()
