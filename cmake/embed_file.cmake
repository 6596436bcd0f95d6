# fw_embed_file(TARGET target SOURCE file SYMBOL name)
# Compiles `file` into `target` as `extern const std::string_view name;`
# (namespace fw::embedded), so the binaries need no files beside them. The
# generated source is rebuilt whenever the file changes.
set(FW_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_file_script.cmake)

function(fw_embed_file)
  cmake_parse_arguments(ARG "" "TARGET;SOURCE;SYMBOL" "" ${ARGN})
  get_filename_component(source_abs ${ARG_SOURCE} ABSOLUTE)
  set(output ${CMAKE_CURRENT_BINARY_DIR}/embedded/${ARG_SYMBOL}.cpp)
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${source_abs} -DOUTPUT=${output} -DSYMBOL=${ARG_SYMBOL}
            -P ${FW_EMBED_SCRIPT}
    DEPENDS ${source_abs} ${FW_EMBED_SCRIPT}
    COMMENT "Embedding ${ARG_SOURCE}"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${output})
endfunction()
