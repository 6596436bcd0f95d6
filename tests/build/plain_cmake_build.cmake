# cmake -P: configure SOURCE_DIR into BUILD_DIR as a newcomer would, with no
# preset and no generator named, and build the WebAssembly modules (the
# engine's, and the speech's from espeak-ng's C sources) and the codec. Prints "plain build: ok" only when every step succeeded.
if(NOT SOURCE_DIR OR NOT BUILD_DIR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=... -DBUILD_DIR=... -P plain_cmake_build.cmake")
endif()
# A fresh folder each time, so the check is of a first configuration.
file(REMOVE_RECURSE ${BUILD_DIR})
# The generator is CMake's default unless the environment names one: say
# Unix Makefiles outright so a CMAKE_GENERATOR in a developer's environment
# cannot turn the check into a second Ninja build.
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BUILD_DIR} -G "Unix Makefiles" -DFW_BUILD_TESTS=OFF
  RESULT_VARIABLE configured)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "plain build: `cmake -S . -B build` failed (${configured})")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target facewire_model facewire_speech fw_codec -j 2
  RESULT_VARIABLE built)
if(NOT built EQUAL 0)
  message(FATAL_ERROR "plain build: `cmake --build build` of the WebAssembly modules and the codec failed (${built})")
endif()
foreach(output web/engine/facewire_model.js web/engine/facewire_model.wasm
               web/speech/facewire_speech.js web/speech/facewire_speech.wasm)
  if(NOT EXISTS ${BUILD_DIR}/${output})
    message(FATAL_ERROR "plain build: the build said it succeeded but ${output} is missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${BUILD_DIR})
message("plain build: ok")
