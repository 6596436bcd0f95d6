#pragma once
// Where dlib's 68-point shape predictor model is found.
#include <filesystem>
#include <optional>

namespace fw::photo {

/// Debian's libdlib-data installs the model here.
inline constexpr const char* kDefaultLandmarkModel = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat";

/// The model file to load: `configured` if given, else $FACEWIRE_LANDMARK_MODEL
/// if set, else kDefaultLandmarkModel. nullopt if the chosen file is not a
/// readable regular file (the caller says which path it tried and how to fix it).
/// @param[in]  configured  a path from the command line or configuration
/// @param[out] tried       the path that was chosen
std::optional<std::filesystem::path> find_landmark_model(const std::optional<std::filesystem::path>& configured,
                                                         std::filesystem::path& tried);

}  // namespace fw::photo
