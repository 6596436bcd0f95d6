#pragma once
// What a room uses of the server, given whole when the room is made
// (RoomRegistry makes rooms; ServerCore makes the registry once the avatar
// store is open). Nothing here is filled in later, and a room reaches
// nothing else of the server.
#include <atomic>
#include <vector>

#include <boost/asio/thread_pool.hpp>

#include "abuse_log.hpp"
#include "avatar_store.hpp"
#include "face_models.hpp"
#include "face_stepper.hpp"
#include "metrics.hpp"
#include "physics_governor.hpp"
#include "room_bus.hpp"
#include "server_config.hpp"
#include "speech_worker.hpp"

namespace fw::server {

struct RoomServices {
  const ServerConfig& config;
  Metrics& metrics;
  PhysicsGovernor& physics_lod;  ///< physics level of detail under load (config.physics_lod)
  AbuseLog& abuse;               ///< refusals by kind, and the room's events
  boost::asio::thread_pool& workers;  ///< room ticks, encoding
  AvatarStore& store;            ///< the faces members wear
  /// The procedural faces: one replaces an avatar its uploader deleted.
  const std::vector<StoredAvatar>& procedural_faces;
  RoomBus& bus;                  ///< the other nodes (LocalRoomBus alone)
  const std::atomic<bool>& draining;  ///< SIGTERM: no new joins
  SpeechWorker& speech;          ///< makes chat lines' lip-sync tracks off the rooms' strands
  FaceStepper& face_stepper;     ///< steps the physics faces of the rooms' ticks together on `workers`
  /// Every avatar's own face, built once per package version on `workers`
  /// (face_models.hpp); null: every avatar simulates the generic face.
  FaceModels* face_models = nullptr;
};

}  // namespace fw::server
