# Build speed. CI builds the tree twice (Release, then ASan) on two cores,
# so the compile and link time of every target counts twice.

# The mold linker, when it is installed (deploy/install-deps.sh installs it):
# linking the test executables against OpenCV, dlib and OSMesa with GNU ld
# costs seconds each, with mold a fraction of that.
find_program(FW_MOLD NAMES mold)
if(FW_MOLD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12.1)
  add_link_options(-fuse-ld=mold)
endif()

# Precompiled headers. Only third-party headers are precompiled (named in
# angle brackets, so the generated cmake_pch.hxx holds no path of the clone
# and the compiler cache hits across clones; see the Makefile's
# CCACHE_SLOPPINESS). What dominates a Beast or dlib file is template
# instantiation, which a PCH does not save; what it saves is parsing, which
# dominates the many small files that include Asio, GoogleTest or CLI11.
set(FW_PCH_ASIO <boost/asio/io_context.hpp> <boost/asio/steady_timer.hpp> <boost/asio/post.hpp>
                <boost/system/error_code.hpp>)
set(FW_PCH_COMMON <nlohmann/json.hpp> <spdlog/spdlog.h>)
set(FW_PCH_CLI <CLI/CLI.hpp>)
set(FW_PCH_OPENCV <opencv2/core.hpp> <opencv2/imgproc.hpp>)

# fw_precompile(TARGET header...): precompiles the headers for the target's
# C++ files (C files, if any, are left alone).
function(fw_precompile target)
  set(headers)
  foreach(header ${ARGN})
    list(APPEND headers "$<$<COMPILE_LANGUAGE:CXX>:${header}>")
  endforeach()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
