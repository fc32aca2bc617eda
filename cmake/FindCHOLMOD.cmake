# FindCHOLMOD: SuiteSparse 5 (as packaged by Debian 12) ships no CMake configuration, so this
# module locates CHOLMOD and the SuiteSparse libraries it depends on.
#
# Defines the imported target CHOLMOD::CHOLMOD and CHOLMOD_FOUND, CHOLMOD_INCLUDE_DIR,
# CHOLMOD_LIBRARIES. Hints: CHOLMOD_ROOT or SUITESPARSE_ROOT.
include(FindPackageHandleStandardArgs)

find_path(CHOLMOD_INCLUDE_DIR cholmod.h
  HINTS ${CHOLMOD_ROOT} ${SUITESPARSE_ROOT} ENV CHOLMOD_ROOT ENV SUITESPARSE_ROOT
  PATH_SUFFIXES include include/suitesparse suitesparse)

set(_cholmod_parts cholmod amd camd colamd ccolamd suitesparseconfig)
set(CHOLMOD_LIBRARIES "")
foreach(_part IN LISTS _cholmod_parts)
  string(TOUPPER ${_part} _upper)
  find_library(CHOLMOD_${_upper}_LIBRARY NAMES ${_part}
    HINTS ${CHOLMOD_ROOT} ${SUITESPARSE_ROOT} ENV CHOLMOD_ROOT ENV SUITESPARSE_ROOT
    PATH_SUFFIXES lib lib64)
  mark_as_advanced(CHOLMOD_${_upper}_LIBRARY)
  list(APPEND _cholmod_required CHOLMOD_${_upper}_LIBRARY)
  list(APPEND CHOLMOD_LIBRARIES ${CHOLMOD_${_upper}_LIBRARY})
endforeach()

find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_INCLUDE_DIR ${_cholmod_required})
mark_as_advanced(CHOLMOD_INCLUDE_DIR)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD INTERFACE IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARIES}")
endif()
