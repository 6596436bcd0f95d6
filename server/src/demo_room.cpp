#include "demo_room.hpp"

#include "demo_faces.hpp"
#include "room.hpp"
#include "room_registry.hpp"

namespace fw::server {

namespace {
constexpr std::uint32_t kDemoFaces = 8;
}

bool make_demo_avatars(ServerContext& context, std::string& error) {
  for (std::uint32_t i = 0; i < kDemoFaces; ++i) {
    const auto package = make_demo_package(i);
    auto stored = context.store->put(package, error);
    if (!stored) {
      error = "the demo face " + std::to_string(i) + " is not a valid package: " + error;
      return false;
    }
    context.demo_avatars.push_back(std::move(*stored));
  }
  return true;
}

void open_demo_room(ServerContext& context, std::function<void()> seated) {
  auto lobby = context.rooms->find_or_create("lobby", /*persistent=*/true);
  const char* names[] = {"Ada", "Bruno", "Chidi"};  // Ada joins first: she leads
  for (std::uint32_t i = 0; i < 3; ++i) {
    JoinRequest request;
    request.name = names[i];
    request.avatar = context.demo_avatars[i];
    lobby->join(std::move(request));
  }
  lobby->then(std::move(seated));
}

}  // namespace fw::server
