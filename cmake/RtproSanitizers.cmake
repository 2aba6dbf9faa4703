# Sanitizer and fuzzing builds (see tests/fuzz/README.md).
#
# RTPRO_SANITIZE=address,undefined instruments every target, ours and the tests, with the listed
# sanitizers. Any finding ends the process with an error (-fno-sanitize-recover), so a test that
# triggers undefined behaviour fails instead of printing a line nobody reads. Debian's Embree,
# oneTBB, OpenImageIO and the other libraries stay uninstrumented: ASan and UBSan need no
# instrumented dependencies (TSan would, which is why it is not offered here).
#
# RTPRO_FUZZ=ON (clang only) adds libFuzzer's coverage instrumentation to everything and links the
# targets in tests/fuzz/ against libFuzzer. Without it the same targets are built as plain replay
# programs that feed their corpus to the target function once, so every build replays the corpus
# as a CTest.
set(RTPRO_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(RTPRO_FUZZ "Link tests/fuzz/ targets against libFuzzer (clang only)" OFF)

if(RTPRO_SANITIZE)
  add_compile_options(-fsanitize=${RTPRO_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${RTPRO_SANITIZE})
  # Line tables are all a sanitizer report needs for file:line in its stacks; full debug info
  # made the sanitizer build about an eighth slower to compile (clang's last -g option wins).
  add_compile_options($<$<CXX_COMPILER_ID:Clang>:-gline-tables-only>)
  # Default options and the documented leak suppressions, linked into every program built after
  # this point (sanitizer_options.cpp says why each suppression is there).
  add_library(rtpro_sanitizer_options OBJECT ${CMAKE_CURRENT_LIST_DIR}/sanitizer_options.cpp)
  link_libraries(rtpro_sanitizer_options)
endif()

if(RTPRO_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RTPRO_FUZZ needs clang (libFuzzer): configure with CXX=clang++")
  endif()
  # Coverage feedback from our libraries too, not only from the fuzz target's own file.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
