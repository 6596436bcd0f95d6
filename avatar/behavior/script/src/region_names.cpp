#include "fw/script/region_names.hpp"

#include <cctype>
#include <utility>

#include "fw/codec/face_params.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::script {
namespace {

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

constexpr std::array<std::string_view, 7> kPairedRegions = {"brow", "upper_lid", "lower_lid", "cheek",
                                                            "mouth_corner", "jaw", "side"};

struct Alias {
  std::string_view name;
  std::array<std::string_view, 2> regions;
};
constexpr std::array<Alias, 5> kAliases = {{
    {"above_brow", {"forehead", ""}},
    {"below_lower_lid", {"cheek_right", "cheek_left"}},
    {"brows", {"brow_right", "brow_left"}},
    {"cheeks", {"cheek_right", "cheek_left"}},
    {"lips", {"upper_lip", "lower_lip"}},
}};

using codec::ColourRegion;

// A name of a group of colour regions; `all_blush` stands for every region
// FaceParams::blush has.
struct ColourAlias {
  std::string_view name;
  bool all_blush = false;
  std::array<ColourRegion, 2> regions{};
  std::size_t count = 0;
};
constexpr std::array<ColourAlias, 7> kColourAliases = {{
    {"cheeks", false, {ColourRegion::cheek_left, ColourRegion::cheek_right}, 2},
    {"cheek", false, {ColourRegion::cheek_left, ColourRegion::cheek_right}, 2},
    {"ears", false, {ColourRegion::sides, ColourRegion::sides}, 1},
    {"ear", false, {ColourRegion::sides, ColourRegion::sides}, 1},
    {"side", false, {ColourRegion::sides, ColourRegion::sides}, 1},
    {"head", true, {}, 0},
    {"face", true, {}, 0},
}};

}  // namespace

std::vector<std::string> face_regions_for(std::string_view written) {
  const std::string name = lowercase(written);
  for (std::string_view region : kFaceRegionNames)
    if (region == name) return {std::string(region)};
  for (std::string_view paired : kPairedRegions)
    if (paired == name) return {name + "_right", name + "_left"};
  for (const Alias& alias : kAliases) {
    if (alias.name != name) continue;
    std::vector<std::string> out;
    for (std::string_view region : alias.regions)
      if (!region.empty()) out.emplace_back(region);
    return out;
  }
  return {};
}

std::string face_region_names_text() {
  std::string out = "the generic face's ";
  for (std::size_t i = 0; i < kFaceRegionNames.size(); ++i) out += (i ? ", " : "") + std::string(kFaceRegionNames[i]);
  out += "; a paired region without its side (";
  for (std::size_t i = 0; i < kPairedRegions.size(); ++i) out += (i ? ", " : "") + std::string(kPairedRegions[i]);
  out += "); or ";
  for (std::size_t i = 0; i < kAliases.size(); ++i) out += (i ? ", " : "") + std::string(kAliases[i].name);
  return out;
}

std::vector<std::size_t> colour_channels_for(std::string_view written) {
  const std::string name = lowercase(written);
  for (std::size_t c = 0; c < kColourChannelCount; ++c)
    if (colour_channel_name(c) == name) return {c};
  for (const ColourAlias& alias : kColourAliases) {
    if (alias.name != name) continue;
    std::vector<std::size_t> out;
    if (alias.all_blush) {
      for (std::size_t c = 0; c < codec::kColourRegionCount; ++c) out.push_back(c);
    } else {
      for (std::size_t i = 0; i < alias.count; ++i) out.push_back(static_cast<std::size_t>(alias.regions[i]));
    }
    return out;
  }
  return {};
}

std::string_view colour_channel_name(std::size_t channel) {
  return channel < codec::kColourRegionCount ? codec::kColourRegionNames[channel] : std::string_view("pallor");
}

std::string colour_region_names_text() {
  std::string out;
  for (std::size_t c = 0; c < kColourChannelCount; ++c) out += (c ? ", " : "") + std::string(colour_channel_name(c));
  for (const ColourAlias& alias : kColourAliases) out += ", " + std::string(alias.name);
  return out;
}

}  // namespace fw::script
