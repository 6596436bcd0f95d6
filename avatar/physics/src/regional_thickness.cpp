#include "fw/physics/regional_thickness.hpp"

#include <array>
#include <cstddef>

namespace fw::physics {
namespace {

using model::FaceRegion;

// Facial soft-tissue depths, rounded means of adults of normal weight, both
// sexes, from the ultrasound database of De Greef, Claes, Vandermeulen,
// Mollemans, Suetens & Willems, "Large-scale in-vivo Caucasian facial soft
// tissue thickness database for craniofacial reconstruction", Forensic
// Science International 159S (2006) S126-S146 (967 adults, 52 landmarks).
// Each region takes the landmarks that lie in it:
//   forehead, hairline   supraglabella, frontal eminence          ~5 mm
//   brows                supraorbital                              ~6 mm
//   lids                 supra- and suborbital (over the orbit rim)~6 mm
//   nose                 end of nasal bones (rhinion), dorsum    ~3 mm
//   cheeks               inferior malar, mid-maxilla            ~15 mm
//   upper lip, corners   mid-philtrum, upper lip margin         ~12 mm
//   lower lip            lower lip margin                        ~13 mm
//   chin                 chin-lip fold, mental eminence          ~11 mm
//   jaw                  gonion, below the second molar          ~14 mm
//   sides                lateral orbit, zygomatic arch            ~9 mm
constexpr std::array<float, model::kFaceRegionCount> kThicknessMm = [] {
  std::array<float, model::kFaceRegionCount> t{};
  auto set = [&](FaceRegion r, float mm) { t[static_cast<std::size_t>(r)] = mm; };
  set(FaceRegion::forehead, 5.0f);
  set(FaceRegion::hairline, 5.0f);
  set(FaceRegion::brow_right, 6.0f);
  set(FaceRegion::brow_left, 6.0f);
  set(FaceRegion::upper_lid_right, 6.0f);
  set(FaceRegion::upper_lid_left, 6.0f);
  set(FaceRegion::lower_lid_right, 6.0f);
  set(FaceRegion::lower_lid_left, 6.0f);
  set(FaceRegion::nose, 3.0f);
  set(FaceRegion::cheek_right, 15.0f);
  set(FaceRegion::cheek_left, 15.0f);
  set(FaceRegion::upper_lip, 12.0f);
  set(FaceRegion::lower_lip, 13.0f);
  set(FaceRegion::mouth_corner_right, 12.0f);
  set(FaceRegion::mouth_corner_left, 12.0f);
  set(FaceRegion::chin, 11.0f);
  set(FaceRegion::jaw_right, 14.0f);
  set(FaceRegion::jaw_left, 14.0f);
  set(FaceRegion::side_right, 9.0f);
  set(FaceRegion::side_left, 9.0f);
  return t;
}();

}  // namespace

float regional_thickness_mm(model::FaceRegion region) {
  const auto i = static_cast<std::size_t>(region);
  return i < kThicknessMm.size() ? kThicknessMm[i] : 0.0f;
}

}  // namespace fw::physics
