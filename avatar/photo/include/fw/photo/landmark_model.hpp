#pragma once
// Where dlib's 68-point shape predictor model, and OpenCV's face cascade
// (the second detector), are found.
#include <filesystem>
#include <optional>

namespace fw::photo {

/// Debian's libdlib-data installs the model here.
inline constexpr const char* kDefaultLandmarkModel = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat";

/// Debian's opencv-data installs the cascade the finder falls back on when
/// dlib's detector sees no face (a head tilted far back, mostly).
inline constexpr const char* kFallbackFaceCascade = "/usr/share/opencv4/haarcascades/haarcascade_frontalface_alt2.xml";

/// The model file to load: `configured` if given, else $FACEWIRE_LANDMARK_MODEL
/// if set, else kDefaultLandmarkModel. nullopt if the chosen file is not a
/// readable regular file (the caller says which path it tried and how to fix it).
/// @param[in]  configured  a path from the command line or configuration
/// @param[out] tried       the path that was chosen
std::optional<std::filesystem::path> find_landmark_model(const std::optional<std::filesystem::path>& configured,
                                                         std::filesystem::path& tried);

}  // namespace fw::photo
