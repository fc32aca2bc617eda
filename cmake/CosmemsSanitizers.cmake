# COSMEMS_SANITIZE: a comma-separated sanitizer list (e.g. "address,undefined" or "thread"),
# applied to every target of this build so that library, tests and tools agree.
set(COSMEMS_SANITIZE "" CACHE STRING "Sanitizers to build with, e.g. address,undefined")
if(COSMEMS_SANITIZE)
  add_compile_options(-fsanitize=${COSMEMS_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${COSMEMS_SANITIZE})
endif()
