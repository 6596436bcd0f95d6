#pragma once
// FACS action-unit numbers as scripts write them: which numbers exist, what
// they are called, and which of them facewire's faces can show.
#include <string>
#include <string_view>

namespace fw::script {

/// Whether `number` is a FACS action-unit code (Ekman, Friesen & Hager 2002):
/// 1-2, 4-39 and 41-46 for the face, 51-58 for the head, 61-66 for the eyes.
bool is_facs_action_unit(long long number);

/// "inner brow raiser" for 1, ...; empty for numbers that are not FACS codes.
std::string_view facs_action_unit_name(long long number);

/// Whether FaceParams carries `au` (fw::codec::kActionUnits), i.e. whether a
/// face can show it.
bool is_carried_by_faces(long long au);

/// "1, 2, 4, ..., 27": the action units faces carry, for messages.
std::string carried_action_units_text();

/// "1-2, 4-39, 41-46, 51-58 and 61-66", for messages.
std::string_view facs_ranges_text();

}  // namespace fw::script
