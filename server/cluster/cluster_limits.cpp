#include "cluster_limits.hpp"

#include <sstream>

namespace fw::server {

std::string encode_limits(const LimitsNews& news) {
  std::ostringstream out;
  out << "node " << news.node << "\n";
  if (news.beat) out << "beat\n";
  for (const auto& s : news.spent) out << "s " << static_cast<int>(s.rate) << " " << s.tokens << " " << s.key << "\n";
  for (const auto& [key, count] : news.connections) out << "c " << count << " " << key << "\n";
  for (const auto& t : news.tokens) {
    if (t.resume_hash.empty()) out << "r " << t.token_hash << "\n";
    else out << "t " << t.token_hash << " " << t.resume_hash << (t.taken_from.empty() ? "" : " " + t.taken_from) << "\n";
  }
  return out.str();
}

std::optional<LimitsNews> decode_limits(std::string_view message) {
  std::istringstream in{std::string(message)};
  std::string line;
  LimitsNews news;
  if (!std::getline(in, line) || line.rfind("node ", 0) != 0 || line.size() == 5) return std::nullopt;
  news.node = line.substr(5);
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "beat") {
      news.beat = true;
    } else if (kind == "s") {
      int rate = -1;
      AddressLimits::Spent spent;
      fields >> rate >> spent.tokens >> spent.key;
      if (!fields || rate < 0 || rate >= static_cast<int>(kAddressRateCount) || spent.tokens < 0) return std::nullopt;
      spent.rate = static_cast<AddressRate>(rate);
      news.spent.push_back(std::move(spent));
    } else if (kind == "c") {
      std::size_t count = 0;
      std::string key;
      fields >> count >> key;
      if (!fields) return std::nullopt;
      news.connections[key] = count;
    } else if (kind == "t" || kind == "r") {
      TokenNews token;
      fields >> token.token_hash;
      if (kind == "t") fields >> token.resume_hash >> token.taken_from;
      if (token.token_hash.empty() || (kind == "t" && token.resume_hash.empty())) return std::nullopt;
      news.tokens.push_back(std::move(token));
    } else {
      return std::nullopt;
    }
  }
  return news;
}

}  // namespace fw::server
