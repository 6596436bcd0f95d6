#include "fw/physics/muscle_variation.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "fw/model/landmark_template.hpp"

namespace fw::physics {
namespace {

// SplitMix64: a fixed, portable generator, so a seed means the same face
// on every platform.
std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [-1, 1).
float centred_uniform(std::uint64_t& state) {
  return static_cast<float>(double(splitmix64(state) >> 11) / double(1ULL << 53) * 2.0 - 1.0);
}

// The pairs dissection finds absent or much reduced in some people
// (Waller et al. 2008; Pessa et al. 1998 for the zygomatic minor).
constexpr std::array<std::string_view, 3> kVariable = {"procerus", "zygomatic_minor", "risorius"};

// How far each muscle's course moves between people, mm (x lateral, y up;
// origin, insertion), at scale 1 each axis within +- these. Where a
// dissection study measured the spread, about one standard deviation of it;
// where none is known, a modelling choice of a millimetre or two inside the
// muscle's own width, so that it stays on the structures it is attached to.
struct NamedSpread {
  std::string_view name;
  CourseSpread spread;
};
constexpr std::array<NamedSpread, 15> kCourseSpreads = {{
    // The frontalis' bellies run 16-36 deg off the midline, +- 15-20 deg
    // between people (Spiegel, Goerig, Lufler & Hoagland 2009, "Frontalis
    // midline dehiscence", J. Plast. Reconstr. Aesthet. Surg. 62: 21
    // foreheads): over their 40-60 mm a few mm at the galea; at the brow
    // they meet the orbicularis oculi at 88.7 +- 13 deg (Costin, Plesec,
    // Sakolsatayadorn, Rubinstein, McBride & Perry 2015, Ophthal. Plast.
    // Reconstr. Surg. 31: 64 hemifaces): 2 mm.
    {"frontalis_inner", {{5.0f, 5.0f}, {2.0f, 2.0f}}},
    {"frontalis_outer", {{5.0f, 5.0f}, {2.0f, 2.0f}}},
    // Corrugator origin 2.9 +- 1.0 mm (medial) to 14.0 +- 2.8 mm (lateral)
    // from the nasion, its lateral insertion 43.3 +- 2.9 mm from it (Janis,
    // Ghavami, Lemmon, Leedy & Guyuron 2007, "Anatomy of the corrugator
    // supercilii muscle: part I", Plast. Reconstr. Surg. 120(6): 50 muscles).
    {"corrugator", {{2.5f, 1.5f}, {3.0f, 2.0f}}},
    // The procerus is among the muscles found reduced or absent (Waller et
    // al. 2008); no spread measured: as the corrugator's beside it.
    {"procerus", {{2.0f, 3.0f}, {2.0f, 2.0f}}},
    // The levators of the upper lip and ala vary in course (Pessa et al.
    // 1998, Plast. Reconstr. Surg.), unmeasured in mm: within their 10-15
    // mm width.
    {"levator_labii_alaeque_nasi", {{1.5f, 2.0f}, {1.5f, 2.0f}}},
    {"nasalis", {{1.0f, 1.5f}, {1.0f, 1.5f}}},
    {"levator_labii_superioris", {{2.0f, 3.0f}, {2.0f, 2.0f}}},
    // The zygomatic minor's course and size vary most of the midface's,
    // down to its absence (Pessa et al. 1998, Plast. Reconstr. Surg.).
    {"zygomatic_minor", {{3.0f, 4.0f}, {2.0f, 3.0f}}},
    // The zygomaticus major arises from the superior margin of the
    // zygoma's temporal process (Sarilita, Rynn, Mossey & Black 2021,
    // Morphologie 105: 52 hemifaces), 8.5 mm wide (Stoltidou,
    // Dimitrakopoulos, Pateraki, Koebke & Dionyssopoulos 2011, Can. J.
    // Plast. Surg. 19A: 102 muscles): within half its width. Its insertion
    // is the modiolus' (kModiolus).
    {"zygomatic_major", {{4.0f, 4.0f}, {0.0f, 0.0f}}},
    // The buccinator arises from the alveolar processes and the
    // pterygomandibular raphe: bone, little room.
    {"buccinator", {{1.0f, 2.0f}, {0.0f, 0.0f}}},
    // The risorius has "numerous and very variable origins": parotid and
    // masseteric fascia, the platysma, the zygomatic arch (Standring 2016,
    // Gray's Anatomy, 41st ed.), one slender bundle to a wide fan: up and
    // down over the masseter. Across, it keeps to +- 1 mm: there the cheek
    // curves back, and a risorius arising farther round pulls the corner
    // inward like the buccinator, reading as a dimpler (AU 14) instead of
    // the lip stretcher (AU 20) in 2 of 100 people at 3 mm.
    {"risorius", {{1.0f, 4.0f}, {0.0f, 0.0f}}},
    // The depressor anguli oris arises along the mandible's oblique line.
    {"depressor_anguli_oris", {{4.0f, 2.0f}, {0.0f, 0.0f}}},
    {"depressor_labii_inferioris", {{2.0f, 2.0f}, {2.0f, 2.0f}}},
    {"mentalis", {{1.5f, 1.5f}, {1.5f, 1.5f}}},
    {"levator_palpebrae", {{0.0f, 0.0f}, {0.0f, 0.0f}}},  // held by the orbit
}};

// Where the mouth corner's muscles converge varies: lateral to the corner
// in 16.5 % of 279 sides, above it in 41.2 %, below it in 42.3 % (Shimada &
// Gasser 1989, "Variations in the facial muscles at the angle of the
// mouth", Clin. Anat. 2); the modiolus reaches 1-2 cm about the commissure
// (Standring 2016). The muscles inserting there move their insertion
// together. The studies give categories, not millimetres; the spread is
// the part of that range that keeps the corner's action units apart: the
// dimpler (buccinator) and the lip stretcher (risorius) pull it along
// nearly the same line: with the modiolus +- 4 mm up and down a person's
// dimpler came within 0.02 of reading as a lip stretcher over 30 people
// (0.85 with strength alone), at +- 2.5 mm within 0.01 over 100; at
// +- 1.5 mm none of 400 people comes nearer than 0.33 (face_simulation_test).
constexpr CourseSpread kModiolus{{0.0f, 0.0f}, {1.0f, 1.5f}};
constexpr std::array<std::string_view, 4> kModiolusMuscles = {"zygomatic_major", "buccinator", "risorius",
                                                              "depressor_anguli_oris"};

// A bifid zygomaticus major is bilateral in 71.4 % of the people who have
// one (Hu, Jin, Youn, Kwak, Koh, Fontaine & Kim 2008, "An anatomic study
// of the bifid zygomaticus major muscle", J. Craniofac. Surg. 19(2): 70
// hemifaces). With kBifidShare of hemifaces bifid: P(both sides) b and
// P(one side) s with b + s / 2 = kBifidShare, b / (b + s) = 0.714.
constexpr float kBifidBilateral = 0.714f;
constexpr float kBifidBoth = kBifidShare / (1.0f + (1.0f - kBifidBilateral) / (2.0f * kBifidBilateral));
constexpr float kBifidOne = kBifidBoth * (1.0f - kBifidBilateral) / kBifidBilateral;

// The course draws' own stream ("course" in ASCII): a seed's strength
// factors stay what they were.
constexpr std::uint64_t kCourseStream = 0x636f75727365ULL;

bool inserts_at_modiolus(std::string_view name) {
  return std::find(kModiolusMuscles.begin(), kModiolusMuscles.end(), name) != kModiolusMuscles.end();
}

float unit_draw(std::uint64_t& state) { return 0.5f * (centred_uniform(state) + 1.0f); }

}  // namespace

CourseSpread course_spread(std::size_t pair) {
  const auto& definitions = facial_muscle_definitions();
  if (pair >= definitions.size()) return {};
  const std::string_view name = definitions[pair].name;
  CourseSpread spread;
  for (const NamedSpread& s : kCourseSpreads)
    if (s.name == name) spread = s.spread;
  if (inserts_at_modiolus(name)) spread.insertion_mm = kModiolus.insertion_mm;
  return spread;
}

std::array<CourseShift, kMuscleCount> muscle_course_shifts(std::uint64_t seed, float scale) {
  std::array<CourseShift, kMuscleCount> shift{};
  std::uint64_t state = seed ^ kCourseStream;
  const float s = std::clamp(scale, 0.0f, 1.0f) / model::kMillimetresPerUnit;
  // Each axis: the pair's draw and the side's own (kSideCourseShare of it).
  auto draw = [&](glm::vec2 spread_mm, glm::vec2 shared) {
    const glm::vec2 side(centred_uniform(state), centred_uniform(state));
    return s * spread_mm * (shared + kSideCourseShare * side);
  };
  auto pair_draw = [&]() { return glm::vec2(centred_uniform(state), centred_uniform(state)); };
  // The modiolus: one place per person, each side a little its own.
  const glm::vec2 modiolus = pair_draw();
  std::array<glm::vec2, 2> modiolus_side{};
  for (auto& m : modiolus_side) m = draw(kModiolus.insertion_mm, modiolus);
  // A bifid zygomaticus major: on both sides, on one, or on neither.
  const float bifid = unit_draw(state);
  const bool one_left = unit_draw(state) < 0.5f;
  const std::array<bool, 2> bifid_side = {bifid < kBifidBoth || (bifid < kBifidBoth + kBifidOne && one_left),
                                          bifid < kBifidBoth || (bifid < kBifidBoth + kBifidOne && !one_left)};
  for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
    const CourseSpread spread = course_spread(pair);
    const std::string_view name = facial_muscle_definitions()[pair].name;
    const glm::vec2 origin = pair_draw(), insertion = pair_draw();
    for (std::size_t side = 0; side < 2; ++side) {
      CourseShift& c = shift[2 * pair + side];
      c.origin = draw(spread.origin_mm, origin);
      c.insertion = inserts_at_modiolus(name) ? modiolus_side[side] : draw(spread.insertion_mm, insertion);
      if (name == "zygomatic_major" && bifid_side[side]) c.bifid_drop = s * kBifidDropMm;
      // Drawn for the left side; the right side is its mirror image.
      if (side == 1) c.origin.x = -c.origin.x, c.insertion.x = -c.insertion.x;
    }
  }
  return shift;
}

bool universally_present(std::size_t pair) {
  const auto& definitions = facial_muscle_definitions();
  if (pair >= definitions.size()) return false;
  for (std::string_view name : kVariable)
    if (definitions[pair].name == name) return false;
  return true;
}

std::array<float, kMuscleCount> muscle_strength_factors(std::uint64_t seed, float scale) {
  std::array<float, kMuscleCount> factor{};
  std::uint64_t state = seed;
  for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
    const float spread = scale * (universally_present(pair) ? 1.0f : kVariableMuscleFactor);
    const float shared = kPairVariation * centred_uniform(state);
    // Left is 2 pair, right 2 pair + 1 (facial_muscles.hpp).
    for (std::size_t side = 0; side < 2; ++side)
      factor[2 * pair + side] = 1.0f + spread * (shared + kSideVariation * centred_uniform(state));
  }
  return factor;
}

std::uint64_t variation_seed(std::string_view asset) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : asset) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

}  // namespace fw::physics
