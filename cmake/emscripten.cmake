# fw_wasm_module(NAME name OUTPUT_DIR dir SOURCES src... INCLUDES dir...
#                [LANGUAGE C|CXX] [THIRD_PARTY_SOURCES src...]
#                [SYSTEM_INCLUDES dir...] EXPORTS symbol... [COMPILE_OPTIONS opt...]
#                [LINK_OPTIONS opt...])
# Compiles C++ sources with Debian's emscripten (em++; emcc for LANGUAGE C)
# into an ES module
# `dir/name.js` and its `dir/name.wasm`, as part of the normal build: target
# `name`, in ALL. The host compiler builds the rest of the tree; emscripten is
# a second toolchain, so its compilations are custom commands (one per
# source, with a depfile so header changes rebuild them) rather than a CMake
# target of their own.
#
# Only what Debian's package ships prebuilt is used (libc, libc++ with
# exceptions): its system library cache is frozen, and emscripten's ports
# (zlib and others) would be downloaded at build time, which a machine
# without internet cannot do. A missing em++ fails the configuration: the
# browser engine is not optional.
find_program(FW_EMXX NAMES em++)
find_program(FW_EMCC NAMES emcc)
if(NOT FW_EMXX OR NOT FW_EMCC)
  message(FATAL_ERROR "em++ (emscripten) not found: the browser engine (web/engine) is compiled to WebAssembly "
                      "with it. Run deploy/install-deps.sh, or `apt-get install emscripten`.")
endif()
# Emscripten's JavaScript optimiser passes need acorn, which Debian keeps in
# its node module directory rather than emscripten's.
set(FW_EM_ENV ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
# em++ compiles through the compiler cache too, when the host compiler does:
# every fresh build tree (CI's clone, the plain-build check) would otherwise
# compile the module's sources again, about a minute of one core each time.
set(FW_EM_LAUNCHER ${CMAKE_CXX_COMPILER_LAUNCHER})
# -O2 rather than -O3: the module is small, and binaryen's extra passes would
# only lengthen the link.
set(FW_EM_FLAGS -std=c++20 -O2 -fexceptions -DNDEBUG
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough)
# C (another project's library and the C API around it): the same
# optimisation, C's own warnings. THIRD_PARTY_SOURCES are someone else's
# code, compiled as their own build does and without our warnings (-w):
# their warnings are theirs to fix, and would bury ours.
set(FW_EMCC_FLAGS -std=gnu11 -O2 -DNDEBUG -Wall -Wextra -Wpedantic -Wshadow -Wcast-align -Wimplicit-fallthrough)
set(FW_EMCC_THIRD_PARTY_FLAGS -std=gnu11 -O2 -DNDEBUG -fwrapv -w)

function(fw_wasm_module)
  cmake_parse_arguments(ARG "" "NAME;OUTPUT_DIR;LANGUAGE"
                        "SOURCES;THIRD_PARTY_SOURCES;INCLUDES;SYSTEM_INCLUDES;EXPORTS;COMPILE_OPTIONS;LINK_OPTIONS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS OR NOT ARG_NAME OR NOT ARG_OUTPUT_DIR OR NOT ARG_SOURCES)
    message(FATAL_ERROR "fw_wasm_module: NAME, OUTPUT_DIR and SOURCES are required; unknown: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(ARG_LANGUAGE STREQUAL "C")
    set(compiler ${FW_EMCC})
    set(flags ${FW_EMCC_FLAGS})
    set(third_party_flags ${FW_EMCC_THIRD_PARTY_FLAGS})
  elseif(NOT ARG_LANGUAGE OR ARG_LANGUAGE STREQUAL "CXX")
    set(compiler ${FW_EMXX})
    set(flags ${FW_EM_FLAGS})
    set(third_party_flags ${FW_EM_FLAGS} -w)
  else()
    message(FATAL_ERROR "fw_wasm_module: LANGUAGE is C or CXX, not ${ARG_LANGUAGE}")
  endif()
  set(include_flags)
  foreach(dir ${ARG_INCLUDES})
    list(APPEND include_flags -I${dir})
  endforeach()
  foreach(dir ${ARG_SYSTEM_INCLUDES})
    list(APPEND include_flags -isystem ${dir})
  endforeach()
  # Ninja makes an output's folder before running its command; the Unix
  # Makefiles generator does not, and em++ will not write into a missing one.
  set(object_dir ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_objects)
  file(MAKE_DIRECTORY ${object_dir})
  set(objects)
  foreach(source ${ARG_SOURCES} ${ARG_THIRD_PARTY_SOURCES})
    get_filename_component(source_abs ${source} ABSOLUTE)
    get_filename_component(source_name ${source} NAME)
    set(source_flags ${flags})
    if(source IN_LIST ARG_THIRD_PARTY_SOURCES)
      set(source_flags ${third_party_flags})
      # Their absolute paths would make long object names: their folder and name are enough.
      get_filename_component(source_dir ${source_abs} DIRECTORY)
      get_filename_component(source_dir ${source_dir} NAME)
      set(source ${source_dir}/${source_name})
    endif()
    string(MAKE_C_IDENTIFIER "${source}" object_name)
    set(object ${object_dir}/${object_name}.o)
    add_custom_command(
      OUTPUT ${object}
      COMMAND ${FW_EM_ENV} ${FW_EM_LAUNCHER} ${compiler} ${source_flags} ${ARG_COMPILE_OPTIONS} ${include_flags}
              -MD -MF ${object}.d -c ${source_abs} -o ${object}
      DEPENDS ${source_abs}
      DEPFILE ${object}.d
      COMMENT "emscripten ${source}"
      VERBATIM)
    list(APPEND objects ${object})
  endforeach()
  list(JOIN ARG_EXPORTS "," exports)
  set(module ${ARG_OUTPUT_DIR}/${ARG_NAME}.js)
  add_custom_command(
    OUTPUT ${module} ${ARG_OUTPUT_DIR}/${ARG_NAME}.wasm
    COMMAND ${CMAKE_COMMAND} -E make_directory ${ARG_OUTPUT_DIR}
    COMMAND ${FW_EM_ENV} ${compiler} ${flags} ${objects} -o ${module}
            -sEXPORTED_FUNCTIONS=${exports} ${ARG_LINK_OPTIONS}
    DEPENDS ${objects}
    COMMENT "Linking the WebAssembly module ${ARG_NAME}"
    VERBATIM)
  add_custom_target(${ARG_NAME} ALL DEPENDS ${module})
endfunction()
