#pragma once
// Could the physics face say its lines itself? For `facewire-bench sim`:
// English lines' lip-sync tracks (avatar/speech) played through a
// projective physics face on the generic avatar, against the track's own
// face as a client rebuilds it. Rooms show the track's mouth and give the
// tissue no speech (server/simulation README); these figures say how far
// the tissue is from taking it over: its lips must close where the
// track's do, on time, before speech can go through it.
#include <nlohmann/json.hpp>

namespace fw::bench {

/// speech_vs_track_mm (the RMS distance, over the skin vertices and the
/// frames, between the physics face rebuilt from its measured AU and
/// corrective weights and the track's face, AU morphs only),
/// speech_bilabial_gap_mm and speech_bilabial_gap_mm_track (the lips'
/// opening, mean over the track's closures, physics within two frames of
/// each and the track's own), speech_jaw_lag_frames (the lag that best
/// lines the physics face's jaw up with the track's) and speech_frames;
/// the track is read speech_lead_ms ahead. Needs espeak-ng (fails the
/// benchmark without it).
nlohmann::json speech_through_tissue();

}  // namespace fw::bench
