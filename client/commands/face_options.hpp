#pragma once
// Command-line words for a face's parameters: `joy=0.8`, `12L=0.7`,
// `cheeks=0.6`, `10,-5`. Each parser fills FaceParams or says what is wrong.
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::client {

/// Applies every `--emotion NAME=INTENSITY` (joy, sadness, anger, fear,
/// surprise, disgust, cunning, teasing; intensity 0..1).
bool apply_emotions(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error);

/// Applies every `--au N=V`: N a FACS number carried by FaceParams, with L or
/// R for one side of a paired AU (12L=0.7); V in 0..1.
bool apply_action_units(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error);

/// Applies every `--blush REGION=V`: forehead, cheek_left, cheek_right,
/// cheeks, nose, sides; V in 0..1.
bool apply_blush(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error);

/// Parses "A,B" or "A,B,C" numbers into `values` (which gives the count).
bool parse_numbers(const std::string& text, std::vector<double>& values, std::string& error);

}  // namespace fw::client
