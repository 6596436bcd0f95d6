#include "fw/script/region_names.hpp"

#include <gtest/gtest.h>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::script {
namespace {

using Regions = std::vector<std::string>;

TEST(RegionNames, TheRegionListIsTheModelsOwn) {
  ASSERT_EQ(kFaceRegionNames.size(), model::kFaceRegionNames.size());
  for (std::size_t i = 0; i < kFaceRegionNames.size(); ++i) EXPECT_EQ(kFaceRegionNames[i], model::kFaceRegionNames[i]);
}

TEST(RegionNames, FacewireNamesPairedNamesAndThePapersNames) {
  EXPECT_EQ(face_regions_for("forehead"), Regions{"forehead"});
  EXPECT_EQ(face_regions_for("Brow_Left"), Regions{"brow_left"});
  EXPECT_EQ(face_regions_for("Upper_Lid"), (Regions{"upper_lid_right", "upper_lid_left"}));
  EXPECT_EQ(face_regions_for("Above_Brow"), Regions{"forehead"});
  EXPECT_EQ(face_regions_for("Brow"), (Regions{"brow_right", "brow_left"}));
  EXPECT_EQ(face_regions_for("Below_Lower_Lid"), (Regions{"cheek_right", "cheek_left"}));
  EXPECT_TRUE(face_regions_for("Abve_Brow").empty());
  EXPECT_TRUE(face_regions_for("").empty());
  // Every name any mapping gives is a region of the generic face.
  for (const char* name : {"brow", "upper_lid", "lower_lid", "cheek", "mouth_corner", "jaw", "side", "above_brow",
                           "below_lower_lid", "brows", "cheeks", "lips"})
    for (const std::string& region : face_regions_for(name))
      EXPECT_TRUE(model::face_region_from_name(region).has_value()) << name << " -> " << region;
  EXPECT_NE(face_region_names_text().find("above_brow"), std::string::npos);
}

TEST(RegionNames, ThePapersColourRegionsMapOntoFaceParams) {
  using codec::ColourRegion;
  const auto channel = [](ColourRegion r) { return static_cast<std::size_t>(r); };
  EXPECT_EQ(colour_channels_for("forehead"), std::vector<std::size_t>{channel(ColourRegion::forehead)});
  EXPECT_EQ(colour_channels_for("Cheeks"),
            (std::vector<std::size_t>{channel(ColourRegion::cheek_left), channel(ColourRegion::cheek_right)}));
  EXPECT_EQ(colour_channels_for("ears"), std::vector<std::size_t>{channel(ColourRegion::sides)});
  EXPECT_EQ(colour_channels_for("nose"), std::vector<std::size_t>{channel(ColourRegion::nose)});
  EXPECT_EQ(colour_channels_for("head").size(), codec::kColourRegionCount);
  EXPECT_EQ(colour_channels_for("pallor"), std::vector<std::size_t>{kPallorChannel});
  EXPECT_EQ(colour_channels_for("cheek_right"), std::vector<std::size_t>{channel(ColourRegion::cheek_right)});
  EXPECT_TRUE(colour_channels_for("knees").empty());
  for (std::size_t c = 0; c < codec::kColourRegionCount; ++c)
    EXPECT_EQ(colour_channel_name(c), codec::kColourRegionNames[c]);
  EXPECT_EQ(colour_channel_name(kPallorChannel), "pallor");
  EXPECT_NE(colour_region_names_text().find("ears"), std::string::npos);
}

}  // namespace
}  // namespace fw::script
