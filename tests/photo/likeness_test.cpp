// Likeness, as an independent observer sees it: dlib's 68 landmarks on each
// avatar's neutral render (in the head pose the photo shows) against those
// on the photo it was made from, after the similarity that best aligns them.
#include <algorithm>
#include <complex>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "fw/photo/prepare_avatar.hpp"
#include "neutral_readings.hpp"
#include "photo_variants.hpp"
#include "rendered_avatar.hpp"
#include "shared_preparer.hpp"
#include "test_paths.hpp"

namespace fw::photo {
namespace {

using neutral_readings::Landmarks;
using neutral_readings::kRadiansPerDegree;

// Which landmarks a likeness counts: all 68, or all but the mouth's twenty
// (48-67). A photo of a smile or of speech has an avatar whose lips meet at
// rest, as they must: there the two differ by the expression taken out, not
// by the person.
enum class Points { all, without_mouth };
bool counted(std::size_t i, Points points) { return points == Points::all || i < 48; }

// The median distance between b's landmarks and a's after the similarity
// (rotation, scale, shift) that takes a onto b best, in b's inter-ocular
// distances.
float aligned_median_error(const Landmarks& a, const Landmarks& b, Points points = Points::all) {
  // Least-squares similarity in complex numbers: b ~ s * a + t.
  using C = std::complex<double>;
  C mean_a(0), mean_b(0);
  double count = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (counted(i, points)) mean_a += C(a[i].x, a[i].y), mean_b += C(b[i].x, b[i].y), count += 1;
  mean_a /= count, mean_b /= count;
  C cross(0);
  double norm = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!counted(i, points)) continue;
    const C p = C(a[i].x, a[i].y) - mean_a, q = C(b[i].x, b[i].y) - mean_b;
    cross += std::conj(p) * q;
    norm += std::norm(p);
  }
  const C s = cross / norm;
  glm::vec2 right(0.0f), left(0.0f);
  for (int i = 0; i < 6; ++i) right += b[36 + i] / 6.0f, left += b[42 + i] / 6.0f;
  const float inter_ocular = glm::length(left - right);
  std::vector<float> errors;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!counted(i, points)) continue;
    const C moved = s * (C(a[i].x, a[i].y) - mean_a) + mean_b;
    errors.push_back(static_cast<float>(std::abs(moved - C(b[i].x, b[i].y))) / inter_ocular);
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  return errors[errors.size() / 2];
}

struct Person {
  std::string photo;
  Landmarks on_photo{};
  std::vector<Landmarks> on_avatar;  ///< one per render size
};

class Likeness : public ::testing::Test {
 protected:
  // At seven sizes: dlib's points move by a fraction of a pixel with the
  // size, as much as some changes being measured.
  static void SetUpTestSuite() {
    people_ = new std::vector<Person>;
    try {
      for (const std::string name : neutral_readings::kPortraits) {
        Person person;
        person.photo = name;
        person.on_photo = neutral_readings::prepared_portrait(name).report.photo_landmarks;
        for (const int size : neutral_readings::kRenderSizes)
          person.on_avatar.push_back(neutral_readings::seen_at_rest(name, size));
        people_->push_back(person);
      }
    } catch (const std::exception& e) {
      FAIL() << e.what();
    }
  }
  static void TearDownTestSuite() { delete people_; }
  static inline std::vector<Person>* people_ = nullptr;
};

// The mean over the render sizes of the aligned median error: one size's
// reading of a face in glasses varied from 0.024 to 0.052.
float likeness_error(const Person& person, const Landmarks& photo, Points points = Points::all) {
  float sum = 0;
  for (const Landmarks& seen : person.on_avatar) sum += aligned_median_error(seen, photo, points);
  return sum / static_cast<float>(person.on_avatar.size());
}

// What the same measure read, without the mouth, on the avatars of the tree
// before their lips were closed at rest, their irises placed as in the
// photo, their light computed per vertex and their outline cut to the head.
float likeness_before(const std::string& photo) {
  if (photo == "astronaut.png") return 0.0254f;
  if (photo == "grace_hopper.jpg") return 0.0377f;
  return 0.0243f;  // kphotoalbum_jesper.jpg
}

// Likeness kept: over the portraits, the mean reading without the mouth is
// at most what it was. Pooled over three faces and seven sizes it moves by
// about 1 % when the render sizes are shifted by 8-16 px; one face's
// reading moves by 3-5 %, and by 10-15 % with changes no eye sees on the
// renders (relighting per vertex instead of per fragment moved Grace
// Hopper's by 12 %; cutting the head's outline moved Jesper's eyes by a
// pixel at 512 px while his jaw and nose read closer to his photo).
// Each face is held to a bound that a lost likeness crosses (it reads 0.05
// and more, all points or without the mouth): at most 20 % above its own
// reading before.
constexpr float kOneFaceAllowance = 1.2f;

TEST_F(Likeness, EachAvatarsLandmarksFollowItsPhotosClosely) {
  float sum = 0, sum_before = 0;
  for (const Person& person : *people_) {
    const float error = likeness_error(person, person.on_photo);
    const float without_mouth = likeness_error(person, person.on_photo, Points::without_mouth);
    std::cout << person.photo << ": median landmark error " << error << " inter-ocular, without the mouth "
              << without_mouth << " (before " << likeness_before(person.photo) << ")\n";
    EXPECT_LE(error, 0.05f) << person.photo;
    EXPECT_LE(without_mouth, kOneFaceAllowance * likeness_before(person.photo)) << person.photo;
    sum += without_mouth;
    sum_before += likeness_before(person.photo);
  }
  const auto count = static_cast<float>(people_->size());
  std::cout << "without the mouth, mean over the portraits " << sum / count << " (before " << sum_before / count
            << ")\n";
  EXPECT_LE(sum, sum_before);
}

TEST_F(Likeness, EachAvatarIsCloserToItsOwnPhotoThanToAnyOther) {
  for (const Person& person : *people_)
    for (const Person& other : *people_) {
      if (&other == &person) continue;
      EXPECT_LT(likeness_error(person, person.on_photo), likeness_error(person, other.on_photo))
          << person.photo << "'s avatar looks more like " << other.photo;
    }
}

// The astronaut's avatar turned or tilted and prepared again: the pose found
// is the one rendered, and the new avatar, frontal, shows the landmarks of
// the original avatar's frontal render.
class PosedHead : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    PrepError error;
    const auto prepared = test::shared_preparer().prepare(test::encode(test::load_astronaut()), {}, error);
    ASSERT_TRUE(prepared.has_value()) << error.message;
    original_ = new model::AvatarPackage(prepared->package);
    test::RenderedAvatar avatar(*original_, 512, {0.5f, 0.5f, 0.5f});
    const auto frontal = test::shared_preparer().prepare(test::encode(test::to_bgr(avatar.draw(codec::FaceParams{}))),
                                                         {}, error);
    ASSERT_TRUE(frontal.has_value()) << error.message;
    frontal_ = new Landmarks(frontal->report.photo_landmarks);
  }
  static void TearDownTestSuite() {
    delete original_;
    delete frontal_;
  }

  // Renders the avatar in `pose`, prepares the render, and returns what was
  // found; the remade avatar's frontal landmarks go to `remade_frontal`.
  static std::optional<PreparedAvatar> prepare_posed(const codec::FaceParams& pose, Landmarks& remade_frontal) {
    PrepError error;
    test::RenderedAvatar avatar(*original_, 512, {0.5f, 0.5f, 0.5f});
    auto again = test::shared_preparer().prepare(test::encode(test::to_bgr(avatar.draw(pose))), {}, error);
    EXPECT_TRUE(again.has_value()) << error.message;
    if (!again) return again;
    test::RenderedAvatar remade(again->package, 512, {0.5f, 0.5f, 0.5f});
    const auto seen = test::shared_preparer().prepare(test::encode(test::to_bgr(remade.draw(codec::FaceParams{}))),
                                                      {}, error);
    EXPECT_TRUE(seen.has_value()) << "dlib finds no face on the remade avatar: " << error.message;
    if (seen) remade_frontal = seen->report.photo_landmarks;
    return again;
  }
  static inline model::AvatarPackage* original_ = nullptr;
  static inline Landmarks* frontal_ = nullptr;
};

TEST_F(PosedHead, TurnedItsPoseIsFoundAndItsFrontalAvatarMatchesTheFrontalOnes) {
  for (const float yaw_deg : {30.0f, -30.0f}) {
    codec::FaceParams turned;
    turned.head_yaw_rad = yaw_deg * kRadiansPerDegree;
    Landmarks remade{};
    const auto again = prepare_posed(turned, remade);
    ASSERT_TRUE(again.has_value()) << yaw_deg;
    // dlib on a perspective render reads a turn a few degrees larger than
    // the orthographic fit assumes: about 5 degrees at 30.
    EXPECT_NEAR(again->report.head_yaw_deg, yaw_deg, 8.0f);
    EXPECT_LE(aligned_median_error(remade, *frontal_), 0.08f) << yaw_deg;
  }
}

// Tilted back 20 degrees, the avatar made from it is the frontal one again.
// At 30, past what dlib's detector finds, the second detector finds the face
// and the fit reads the tilt; the avatar it makes is rough there (the
// texture of a face seen from below), so only the finding is asserted.
TEST_F(PosedHead, TiltedBackItIsFoundAndItsTiltTakenOut) {
  codec::FaceParams tilted;
  tilted.head_pitch_rad = 20.0f * kRadiansPerDegree;
  Landmarks remade{};
  const auto again = prepare_posed(tilted, remade);
  ASSERT_TRUE(again.has_value());
  EXPECT_NEAR(again->report.head_pitch_deg, 20.0f, 8.0f);
  EXPECT_LE(aligned_median_error(remade, *frontal_), 0.08f);

  tilted.head_pitch_rad = 30.0f * kRadiansPerDegree;
  test::RenderedAvatar avatar(*original_, 512, {0.5f, 0.5f, 0.5f});
  PrepError error;
  const auto far = test::shared_preparer().prepare(test::encode(test::to_bgr(avatar.draw(tilted))), {}, error);
  ASSERT_TRUE(far.has_value()) << error.message;
  // The fit reads a tilt a little smaller: the shape predictor's landmarks
  // on a face seen from below gather toward the middle.
  EXPECT_NEAR(far->report.head_pitch_deg, 30.0f, 10.0f);
}

}  // namespace
}  // namespace fw::photo
