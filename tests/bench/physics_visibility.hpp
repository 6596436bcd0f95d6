#pragma once
// What of the physics face a viewer could see, for `facewire-bench sim`:
// the held-out behaviour corpus (avatar/physics/corpus/held_out.txt)
// simulated as a room does, on people the corrective fit never saw,
// rebuilt as a client would.
#include <string>

#include <nlohmann/json.hpp>

namespace fw::bench {

/// physics_vs_kinematic_mm (the RMS distance, over the skin vertices and the
/// corpus frames, between the physics face rebuilt from its measured AU and
/// corrective weights and the kinematic fallback's face, AU morphs only),
/// the same without the correctives, corrective_error_cut (the error
/// against the simulated skin with the correctives over without), and
/// the simulated skin's own distances: simulated_skin_vs_kinematic_mm (the
/// projective solver's, what a perfect corrective basis would show),
/// reference_skin_vs_kinematic_mm (the mass-spring solver's on the same
/// corpus and people) and projective_vs_reference_mm (the two skins apart).
/// @param[in] corpus_path  a behaviour corpus file
nlohmann::json physics_visibility(const std::string& corpus_path);

}  // namespace fw::bench
