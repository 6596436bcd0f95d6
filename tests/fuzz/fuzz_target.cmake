# fw_fuzz_target(NAME name SOURCES ... [INCLUDES ...] [SEEDS file...] [SECONDS s]
#                [LINK -lfoo...] [AFTER target...])
#
# Builds a libFuzzer target with Debian's clang (the main build may use GCC,
# which has no libFuzzer): the listed sources, the fuzz entry point among
# them, are compiled together with -fsanitize=fuzzer,address,undefined so the
# code under test carries coverage instrumentation. They must need nothing
# but the C++ standard library, the INCLUDES and the LINK flags; AFTER names
# targets that generate any of the sources. A ctest test (label `fuzz`)
# runs it for SECONDS (default 20) from the seed corpus in
# tests/fuzz/corpus/NAME (if there is one) plus the SEEDS files, and fails on
# any crash, leak or sanitizer report.
find_program(FW_CLANGXX NAMES clang++-14 clang++)

function(fw_fuzz_target)
  cmake_parse_arguments(ARG "" "NAME;SECONDS" "SOURCES;INCLUDES;SEEDS;LINK;AFTER" ${ARGN})
  if(NOT FW_CLANGXX)
    message(WARNING "clang++ not found: fuzz target ${ARG_NAME} is not built (run deploy/install-deps.sh)")
    return()
  endif()
  if(NOT ARG_SECONDS)
    set(ARG_SECONDS 20)
  endif()
  set(output ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME})
  set(sources)
  foreach(source ${ARG_SOURCES})
    get_filename_component(absolute ${source} ABSOLUTE)
    list(APPEND sources ${absolute})
  endforeach()
  set(includes)
  foreach(dir ${ARG_INCLUDES})
    get_filename_component(absolute ${dir} ABSOLUTE)
    list(APPEND includes -I${absolute})
  endforeach()
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/fuzz
    COMMAND ${FW_CLANGXX} -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined
            -fno-sanitize-recover=undefined ${includes} ${sources} ${ARG_LINK} -o ${output}
    DEPENDS ${sources}
    COMMENT "Building fuzz target ${ARG_NAME} with clang"
    VERBATIM)
  add_custom_target(${ARG_NAME} ALL DEPENDS ${output})
  if(ARG_AFTER)
    add_dependencies(${ARG_NAME} ${ARG_AFTER})
  endif()
  set(corpus ${CMAKE_CURRENT_SOURCE_DIR}/corpus/${ARG_NAME})
  set(work ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME}-corpus)
  set(seeds "")
  foreach(seed ${ARG_SEEDS})
    get_filename_component(absolute ${seed} ABSOLUTE)
    string(APPEND seeds " '${absolute}'")
  endforeach()
  # Fuzz into a scratch copy of the seeds so the source tree stays clean.
  add_test(NAME fuzz_${ARG_NAME}
    COMMAND sh -c "rm -rf '${work}' && mkdir -p '${work}' && { cp -r '${corpus}'/. '${work}'/ 2>/dev/null; \
for s in ${seeds}; do cp \"$s\" '${work}'/; done; } ; \
'${output}' -max_total_time=${ARG_SECONDS} -timeout=5 -rss_limit_mb=1024 -print_final_stats=1 '${work}'")
  set_tests_properties(fuzz_${ARG_NAME} PROPERTIES LABELS "fuzz;slow" TIMEOUT ${ARG_SECONDS}0)
endfunction()
