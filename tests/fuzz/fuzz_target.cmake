# fw_fuzz_target(NAME name SOURCES ... [INCLUDES ...] [SEEDS file...] [SECONDS s]
#                [LINK -lfoo...] [AFTER target...] [SEEDS_MUST_READ])
#
# Builds a libFuzzer target with Debian's clang (the main build may use GCC,
# which has no libFuzzer): the listed sources, the fuzz entry point among
# them, are compiled one by one (through the compiler cache, when there is
# one; a source that several targets list, once for all) with
# -fsanitize=fuzzer,address,undefined so the code under test carries
# coverage instrumentation, then linked. They must need nothing but
# the C++ standard library, the INCLUDES and the LINK flags; AFTER names
# targets that generate any of the sources. A ctest test (labels `fuzz` and
# `slow`) runs it for SECONDS (default 5) from the seed corpus in
# tests/fuzz/corpus/NAME (if there is one) plus the SEEDS files, and fails on
# any crash, leak or sanitizer report; `make fuzz` runs every target for as
# long as you ask (tests/fuzz/run_fuzzers.sh).
#
# SEEDS_MUST_READ: every seed is an input the code reads (none is there to
# be refused), and the target calls seed_refused() (seed_check.hpp) where it
# refuses one. The test then runs the seeds once with
# FW_FUZZ_SEEDS_MUST_READ set before it fuzzes, and fails if one has gone
# stale (an old version, say), since a stale seed explores nothing past the
# check that refuses it.
#
# The sanitizer build (FW_SANITIZE) builds no fuzz target: they carry their
# own sanitizers and run in the release pass only.
find_program(FW_CLANGXX NAMES clang++-14 clang++)
find_program(FW_CCACHE NAMES ccache)
# -O1 makes a fuzzer run about twice as fast and takes twice as long to
# compile, and the fuzz objects are a fifth of a cold build's compile time.
# make test runs each target for 5 s from its seeds, where the compile time
# counts and the speed hardly does: -O0. make fuzz, which runs them for
# minutes, turns this on.
option(FW_FUZZ_OPTIMIZE "Compile the fuzz targets with -O1 (for long fuzzing runs)" OFF)

function(fw_fuzz_target)
  cmake_parse_arguments(ARG "SEEDS_MUST_READ" "NAME;SECONDS" "SOURCES;INCLUDES;SEEDS;LINK;AFTER" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "fw_fuzz_target(${ARG_NAME}): unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(FW_SANITIZE)
    return()
  endif()
  if(NOT FW_CLANGXX)
    message(WARNING "clang++ not found: fuzz target ${ARG_NAME} is not built (run deploy/install-deps.sh)")
    return()
  endif()
  if(NOT ARG_SECONDS)
    set(ARG_SECONDS 5)
  endif()
  set(output ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME})
  # One object per source for all targets: the codec and the asset reader
  # serve several of them and compile once.
  set(object_dir ${CMAKE_BINARY_DIR}/fuzz/objects)
  set(includes)
  foreach(dir ${ARG_INCLUDES})
    get_filename_component(absolute ${dir} ABSOLUTE)
    list(APPEND includes -I${absolute})
  endforeach()
  if(FW_FUZZ_OPTIMIZE)
    set(optimize -O1)
  else()
    set(optimize -O0)
  endif()
  set(flags -std=c++20 ${optimize} -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined)
  set(objects)
  foreach(source ${ARG_SOURCES})
    get_filename_component(absolute ${source} ABSOLUTE)
    # One object per source, named after its path so that equal file names
    # in different folders do not collide.
    file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR} ${absolute})
    string(REGEX REPLACE "[/.]" "_" object_name "${relative}")
    set(object ${object_dir}/${object_name}.o)
    list(APPEND objects ${object})
    # Compiled with the INCLUDES of the first target that lists it (every
    # target's own suffice for all of its sources).
    get_property(compiled GLOBAL PROPERTY FW_FUZZ_OBJECTS)
    if(object IN_LIST compiled)
      continue()
    endif()
    set_property(GLOBAL APPEND PROPERTY FW_FUZZ_OBJECTS ${object})
    add_custom_command(
      OUTPUT ${object}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${object_dir}
      COMMAND ${FW_CCACHE} ${FW_CLANGXX} ${flags} ${includes} -MD -MF ${object}.d -c ${absolute} -o ${object}
      DEPENDS ${absolute}
      DEPFILE ${object}.d
      COMMENT "Compiling ${relative} for the fuzz targets"
      VERBATIM)
  endforeach()
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${FW_CLANGXX} ${flags} ${objects} ${ARG_LINK} -o ${output}
    DEPENDS ${objects}
    COMMENT "Linking fuzz target ${ARG_NAME}"
    VERBATIM)
  add_custom_target(${ARG_NAME} ALL DEPENDS ${output})
  if(ARG_AFTER)
    add_dependencies(${ARG_NAME} ${ARG_AFTER})
  endif()
  set(corpus ${CMAKE_CURRENT_SOURCE_DIR}/corpus/${ARG_NAME})
  set(seeds "")
  foreach(seed ${ARG_SEEDS})
    get_filename_component(absolute ${seed} ABSOLUTE)
    list(APPEND seeds ${absolute})
  endforeach()
  # What `make fuzz` (run_fuzzers.sh) needs of each target: one line of
  # run_fuzzer.sh's arguments after SECONDS.
  string(REPLACE ";" " " seed_words "${seeds}")
  file(WRITE ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME}.args
       "${output} ${corpus} ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME}-corpus ${seed_words}\n")
  add_test(NAME fuzz_${ARG_NAME}
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/fuzz/run_fuzzer.sh ${ARG_SECONDS} ${output} ${corpus}
            ${CMAKE_BINARY_DIR}/fuzz/${ARG_NAME}-corpus ${seeds})
  math(EXPR timeout "${ARG_SECONDS} * 3 + 60")
  # COST: start the long runs first, so that they do not trail the others.
  # PROCESSORS 2: a fuzzer keeps a whole core busy (tests/CMakeLists.txt, CORES).
  set_tests_properties(fuzz_${ARG_NAME} PROPERTIES LABELS "fuzz;slow" TIMEOUT ${timeout} COST ${ARG_SECONDS}
                       PROCESSORS 2)
  if(ARG_SEEDS_MUST_READ)
    set_tests_properties(fuzz_${ARG_NAME} PROPERTIES ENVIRONMENT FW_FUZZ_SEEDS_MUST_READ=1)
  endif()
endfunction()
