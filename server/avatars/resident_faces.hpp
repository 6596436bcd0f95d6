#pragma once
// The lobby's residents: avatar packages prepared from portraits that ship
// with the project (server/avatars/residents/README.md gives each one's
// source and licence), compiled into the server. They are made the way a
// person's avatar is made, by the photo pipeline, ahead of time: preparing
// them at every start would cost each server (and each test that starts
// one) a landmark model and seconds of CPU.
#include <span>
#include <string_view>

namespace fw::server {

struct ResidentFace {
  std::string_view name;      ///< as seated in the lobby
  std::string_view portrait;  ///< the photo it was prepared from, from the project's root
  std::string_view package;   ///< the .fwa's bytes
};

/// The residents, in the order they are seated (the first leads).
std::span<const ResidentFace> resident_faces();

}  // namespace fw::server
