#include "fw/codec/face_params.hpp"

// FaceParams is plain data; this unit exists so the codec target compiles its
// header on its own and checks the invariants the bitstream relies on.
namespace fw::codec {
static_assert(action_unit_index(12) == 8);
static_assert(action_unit_index(3) == -1);
static_assert(kColourRegionNames.size() == kColourRegionCount);
}  // namespace fw::codec
