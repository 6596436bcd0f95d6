#include "mute_list.hpp"

namespace fw::client {

std::vector<std::string> MuteList::notices(const std::vector<codec::AvatarInfo>& avatars, std::uint32_t you) const {
  std::vector<std::string> lines;
  for (const std::string& name : names_) {
    int wearing = 0;
    for (const codec::AvatarInfo& info : avatars) wearing += mutes(info.id, info.name, you) && info.name == name ? 1 : 0;
    std::string line = "muted " + name + " for you alone (their lines are not printed, their face is drawn still; "
                       "nobody else is affected and they are not told)";
    if (wearing == 0)
      line += ": nobody of that name is here yet, whoever comes under it is muted";
    else if (wearing > 1)
      line += ": " + std::to_string(wearing) + " people here share that name, all of them are muted";
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace fw::client
