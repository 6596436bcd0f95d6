#pragma once
// Golden file of packages put back together from their chunks
// (client/room/package_assembler), which the browser's
// web/room/package_assembly.js ports: runs of chunks in order, interleaved,
// restarted, with gaps, past their end, announced too large, and avatars
// forgotten midway, with what each chunk completes or refuses.
#include <nlohmann/json.hpp>

namespace fw::test::web_golden {

nlohmann::json package_assembly_golden();

}  // namespace fw::test::web_golden
