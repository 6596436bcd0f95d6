// The person at rest, as an independent observer sees it: dlib's 68 points
// on each committed portrait and on its avatar's neutral render, in the head
// pose the photo shows (each measure the median over seven render sizes).
// The face is found; the eyes open as far as in the photo (unless the
// photo's expression narrowed them); the lips meet.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/photo/prepare_avatar.hpp"
#include "neutral_readings.hpp"
#include "photo_expression.hpp"

namespace fw::photo {
namespace {

using neutral_readings::Landmarks;

// Soukupova & Cech's eye aspect ratio ("Real-Time Eye Blink Detection using
// Facial Landmarks", 2016): the two lid-to-lid heights over the eye's width,
// on the 68-point scheme's six points an eye. Open eyes read about 0.25-0.35,
// closed ones under 0.2.
float eye_aspect_ratio(const Landmarks& p, int first) {
  const auto d = [&](int a, int b) { return glm::length(p[first + a] - p[first + b]); };
  return (d(1, 5) + d(2, 4)) / (2.0f * d(0, 3));
}
float mean_eye_aspect_ratio(const Landmarks& p) { return 0.5f * (eye_aspect_ratio(p, 36) + eye_aspect_ratio(p, 42)); }

// The inner lips' gap (points 61-67, 62-66, 63-65) over the mouth's width
// (48-54): dlib's points on lips that meet are a pixel or two apart.
float lip_gap(const Landmarks& p) {
  const float gap = (glm::length(p[61] - p[67]) + glm::length(p[62] - p[66]) + glm::length(p[63] - p[65])) / 3.0f;
  return gap / glm::length(p[54] - p[48]);
}

// Lips that meet. dlib reads 0.017 on a photo of closed lips (Grace
// Hopper's) but about 0.05 on her avatar's render, whose lips meet in the
// mesh and show her own line between them: a render is softer than the
// photo (her texture holds 59 px per unit where her photo has 81), and dlib's
// shape regression weighs the whole face. Lips apart read 0.09 and more (the
// astronaut's and Jesper's neutral mouths when the photo's teeth and a slit
// showed between them: 0.088 and 0.095; their photos: 0.13 and 0.19).
// The bound lies between: Jesper's closed rest mouth reads 0.058 to 0.071
// as the physics AU basis that undoes his photo's open jaw changes (0.063
// with the face's regional tissue depths, 0.071 with the jaw's glide and
// the solvers' bone damping as well), still well under the 0.088 of lips
// apart.
constexpr float kClosedLipGap = 0.075f;

float au(const PrepReport& report, int unit, codec::AuSide side) {
  return report.photo_expression[static_cast<std::size_t>(codec::au_channel(unit, side))];
}

// How much wider the generic face's eyes are at rest than with the cheek
// raiser (AU6, which lifts the lower lids) at `intensity`: how far the
// photo's own expression had closed them, and so how far the neutral face
// may open them past the photo's.
float opening_undone(float intensity) {
  const model::GenericFace& generic = model::generic_face();
  Landmarks rest{}, narrowed{};
  const auto tmpl = model::landmark_template();
  std::copy(tmpl.begin(), tmpl.end(), rest.begin());
  narrowed = rest;
  for (const codec::AuSide side : {codec::AuSide::left, codec::AuSide::right}) {
    const model::Morph& morph = generic.action_units[static_cast<std::size_t>(codec::au_channel(6, side))];
    for (std::size_t i = 0; i < narrowed.size(); ++i) narrowed[i] += intensity * picture_motion(generic, morph, i);
  }
  return mean_eye_aspect_ratio(rest) / mean_eye_aspect_ratio(narrowed);
}

// dlib's inner-lip and lid points move by a pixel or two from one render of
// the same face to the next (its shape regression sees the whole face), so
// each measure is the median over renders at seven sizes.

float median(std::vector<float> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

struct RestReading {
  std::string photo;
  PrepReport report;
  float rest_eye_aspect_ratio = 0, rest_lip_gap = 0;
};

class PersonAtRest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    people_ = new std::vector<RestReading>;
    try {
      for (const std::string name : neutral_readings::kPortraits) {
        std::vector<float> eye_ratios, lip_gaps;
        for (const int size : neutral_readings::kRenderSizes) {
          const Landmarks& seen = neutral_readings::seen_at_rest(name, size);
          eye_ratios.push_back(mean_eye_aspect_ratio(seen));
          lip_gaps.push_back(lip_gap(seen));
        }
        people_->push_back(
            {name, neutral_readings::prepared_portrait(name).report, median(eye_ratios), median(lip_gaps)});
      }
    } catch (const std::exception& e) {
      FAIL() << e.what();
    }
  }
  static void TearDownTestSuite() { delete people_; }
  static inline std::vector<RestReading>* people_ = nullptr;
};

TEST_F(PersonAtRest, TheFaceIsFoundAtThePhotosPose) {
  // SetUpTestSuite asserts that dlib finds each neutral face; all three did.
  EXPECT_EQ(people_->size(), 3u);
}

// The allowance for a photo whose smile narrowed the eyes is real: the
// generic face's cheek raiser at full intensity closes its eyes by a
// measurable part, and more intensity closes them more.
TEST(OpeningUndone, TheCheekRaiserNarrowsTheEyes) {
  EXPECT_FLOAT_EQ(opening_undone(0.0f), 1.0f);
  std::cout << "the generic face's cheek raiser at 0.5 and 1 narrows its eyes " << opening_undone(0.5f) << "x, "
            << opening_undone(1.0f) << "x\n";
  EXPECT_GT(opening_undone(0.5f), 1.0f);
  EXPECT_GT(opening_undone(1.0f), opening_undone(0.5f));
}

TEST_F(PersonAtRest, EyesOpenAsFarAsInThePhoto) {
  ASSERT_EQ(people_->size(), 3u);
  for (const RestReading& person : *people_) {
    const float photo_ear = mean_eye_aspect_ratio(person.report.photo_landmarks);
    const float narrowing = std::max(au(person.report, 6, codec::AuSide::left), au(person.report, 6, codec::AuSide::right));
    const float undone = opening_undone(narrowing);
    const float ratio = person.rest_eye_aspect_ratio / photo_ear;
    std::cout << person.photo << ": eye aspect ratio photo " << photo_ear << ", at rest " << person.rest_eye_aspect_ratio
              << " (" << ratio << "x), cheek raiser " << narrowing << " (opens the eyes " << undone << "x)\n";
    // Within 15 % of the photo's, or of the photo's opened by as much as its
    // cheek raiser had closed them: never a stare the photo did not show.
    EXPECT_GE(ratio, 0.85f) << person.photo << "'s eyes at rest are narrower than in the photo";
    EXPECT_LE(ratio, 1.15f * undone) << person.photo << "'s eyes at rest are wider than in the photo";
  }
}

TEST_F(PersonAtRest, LipsMeet) {
  ASSERT_EQ(people_->size(), 3u);
  for (const RestReading& person : *people_) {
    std::cout << person.photo << ": lip gap photo " << lip_gap(person.report.photo_landmarks) << ", at rest "
              << person.rest_lip_gap << "\n";
    EXPECT_LT(person.rest_lip_gap, kClosedLipGap) << person.photo << "'s lips at rest are apart";
  }
}

}  // namespace
}  // namespace fw::photo
