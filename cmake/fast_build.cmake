# Build speed. CI builds the tree twice (Release, then ASan) on two cores,
# so the compile and link time of every target counts twice.

# The mold linker, when it is installed (deploy/install-deps.sh installs it):
# linking the test executables against OpenCV, dlib and OSMesa with GNU ld
# costs seconds each, with mold a fraction of that.
find_program(FW_MOLD NAMES mold)
if(FW_MOLD AND (CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR
                (CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12.1)))
  add_link_options(-fuse-ld=mold)
endif()

# Precompiled headers, for the one place they pay: GoogleTest in the test
# files (tests/CMakeLists.txt). Measured on this tree with GCC 12: a Beast,
# dlib or JSON file spends its time instantiating templates, which a PCH does
# not save (5 % on http_session.cpp), and a PCH of Asio, CLI11 and JSON
# (190 MB) made a small client file take 7 s instead of 0.6 s to load it.
# Only third-party headers in angle brackets are precompiled, so that the
# generated cmake_pch.hxx holds no path of the clone and the compiler cache
# hits across clones (see the Makefile's CCACHE_SLOPPINESS).
#
# fw_precompile(TARGET header...): precompiles the headers for the target's
# C++ files (C files, if any, are left alone).
function(fw_precompile target)
  set(headers)
  foreach(header ${ARGN})
    list(APPEND headers "$<$<COMPILE_LANGUAGE:CXX>:${header}>")
  endforeach()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
