# Runs at build time: turns INPUT into a C++ source defining fw::embedded::SYMBOL.
# Bytes are written as a hex array (raw string literals have length limits and
# the input may contain any byte).
file(READ ${INPUT} content HEX)
get_filename_component(INPUT_NAME ${INPUT} NAME)
string(LENGTH "${content}" hex_length)
math(EXPR byte_count "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${content}")
string(REGEX REPLACE "(('\\\\x..',){32})" "\\1\n" bytes "${bytes}")
file(WRITE ${OUTPUT}
"// Generated from ${INPUT_NAME}; do not edit.\n#include <string_view>\nnamespace fw::embedded {\nstatic const char ${SYMBOL}_bytes[] = {\n${bytes}'\\0'};\nextern const std::string_view ${SYMBOL};\nconst std::string_view ${SYMBOL}(${SYMBOL}_bytes, ${byte_count});\n}\n")
