# Script mode: install, check the installed layout, configure, build and run the consumer.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

if(CONFIG)
  run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}" --config "${CONFIG}")
else()
  run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
endif()

foreach(path bin/cosmems include/cosmems/cosmems.hpp)
  if(NOT EXISTS "${prefix}/${path}")
    message(FATAL_ERROR "missing from the installed tree: ${path}")
  endif()
endforeach()
file(GLOB_RECURSE config "${prefix}/*/cosmemsConfig.cmake")
if(NOT config)
  message(FATAL_ERROR "missing from the installed tree: cosmemsConfig.cmake")
endif()

run(${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer")
run("${prefix}/bin/cosmems" --version)
