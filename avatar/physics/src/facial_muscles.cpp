#include "fw/physics/facial_muscles.hpp"

#include <cassert>

namespace fw::physics {
namespace {

// Anchors are for the person's left side (x > 0). Origins sit on the bone
// where anatomy atlases put them; insertions on the skin the muscle moves.
// Model units: 1 = inter-ocular distance (63 mm). Strengths are calibrated so
// that each action unit alone moves the skin about as far as the face's
// geometric action unit did (see tools/, `facewire-aubasis --report`); the
// frontalis a little further, so that the brow hairs, half of whose motion
// is the texture's, rise with the brow.
constexpr FaceAnchor at(float x, float y) { return {-1, -1, {x, y}}; }
constexpr FaceAnchor on(int landmark, float dx = 0.0f, float dy = 0.0f) { return {landmark, -1, {dx, dy}}; }
constexpr FaceAnchor between(int a, int b, float dx = 0.0f, float dy = 0.0f) { return {a, b, {dx, dy}}; }

MuscleDefinition linear(std::string_view name, float strength, FaceAnchor origin, FaceAnchor insertion, float width,
                        float reach, float origin_depth = 0.0f, bool on_jaw = false) {
  MuscleDefinition m;
  m.name = name;
  m.kind = MuscleKind::linear;
  m.strength = strength;
  m.origin = origin;
  m.insertion = insertion;
  m.width = width;
  m.reach = reach;
  m.origin_depth = origin_depth;
  m.origin_on_jaw = on_jaw;
  return m;
}

MuscleDefinition of_the_nose(MuscleDefinition m) {
  m.moves_nose = true;
  return m;
}

MuscleDefinition in_the_lips(MuscleDefinition m) {
  m.within_the_lips = true;
  return m;
}

MuscleDefinition sphincter(std::string_view name, float strength, FaceAnchor centre, glm::vec2 semi_axes, float ring,
                           glm::vec3 pull_scale, float upper_share, bool half) {
  MuscleDefinition m;
  m.name = name;
  m.kind = MuscleKind::sphincter;
  m.strength = strength;
  m.centre = centre;
  m.semi_axes = semi_axes;
  m.ring = ring;
  m.pull_scale = pull_scale;
  m.upper_share = upper_share;
  m.half = half;
  return m;
}

// A jaw muscle turns the mandible; it does not pull the skin (it lies under
// the mimetic muscles, on the bone), but its belly may bulge under it.
MuscleDefinition jaw(std::string_view name, float angle_rad, FaceAnchor origin, FaceAnchor insertion, float width,
                     float bulge_mm = 0.0f) {
  MuscleDefinition m = linear(name, 0.0f, origin, insertion, width, 0.1f, 0.15f, false);
  m.kind = MuscleKind::jaw;
  m.jaw_angle_rad = angle_rad;
  m.bulge_mm = bulge_mm;
  return m;
}

std::array<MuscleDefinition, kMusclesPerSide> make_definitions() {
  return {{
      // Brows and forehead: the frontalis, in a medial and a lateral belly,
      // from the galea aponeurotica above the hairline down to the brow (the
      // lateral one toward its outer third, so that over the thin forehead
      // tissue the brow's tail rises with the rest).
      linear("frontalis_inner", 136.0f, at(0.22f, 1.3f), on(22, 0.05f, 0.03f), 0.3f, 0.14f),
      linear("frontalis_outer", 105.0f, at(0.75f, 1.25f), on(25, 0.05f, 0.03f), 0.3f, 0.14f),
      // From the nasal part of the frontal bone to the middle of the brow:
      // pulls the brow down and in (AU 4).
      linear("corrugator", 201.0f, at(0.07f, 0.12f), on(23, 0.05f, 0.0f), 0.16f, 0.14f, 0.05f),
      // From the nasal bone up to the skin between the brows.
      of_the_nose(linear("procerus", 195.0f, at(0.03f, -0.3f), on(22, -0.1f, 0.03f), 0.13f, 0.12f)),
      // Lifts the upper lid from the roof of the orbit (AU 5).
      linear("levator_palpebrae", 162.0f, at(0.5f, 0.45f), between(43, 44, 0.0f, 0.0f), 0.16f, 0.05f),
      // Orbicularis oculi: the orbital part gathers cheek and brow toward the
      // eye (AU 6, mostly the lower half); the palpebral part narrows the lids (AU 7).
      sphincter("orbicularis_oculi_orbital", 240.0f, between(42, 45, 0.0f, -0.02f), {0.4f, 0.3f}, 0.55f,
                {0.5f, 1.0f, 0.2f}, 0.3f, false),
      sphincter("orbicularis_oculi_palpebral", 272.0f, between(42, 45), {0.24f, 0.1f}, 0.6f, {0.1f, 1.0f, 0.0f},
                0.45f, false),
      // Nose and upper lip.
      of_the_nose(linear("levator_labii_alaeque_nasi", 276.0f, at(0.11f, -0.05f), on(35, 0.04f, -0.1f), 0.15f, 0.12f)),
      // The nasalis' transverse part runs from the maxilla beside the nose
      // up over its side into an aponeurosis across the dorsum, which the
      // procerus ties to the nasal bones. In AU 9 it gathers the side of
      // the nose up and in toward that aponeurosis, wrinkling the dorsum
      // and the sides while the levator raises the ala (FACS manual, AU 9):
      // its fixed end here is the dorsum, its pull on the side and ala (laid
      // from the maxilla below, it drew the side of the nose down, against
      // the lift).
      of_the_nose(linear("nasalis", 113.0f, at(0.03f, -0.28f), at(0.2f, -0.62f), 0.15f, 0.1f)),
      linear("levator_labii_superioris", 200.0f, at(0.3f, -0.33f), on(52, 0.05f, 0.0f), 0.15f, 0.1f),
      linear("zygomatic_minor", 213.0f, at(0.56f, -0.42f), on(53, 0.02f, 0.0f), 0.13f, 0.1f),
      // The mouth corner's muscles meet at the modiolus beside the corner.
      linear("zygomatic_major", 492.0f, at(0.92f, -0.45f), on(54), 0.2f, 0.12f),
      linear("buccinator", 430.0f, at(0.72f, -1.05f), on(54), 0.16f, 0.08f, 0.25f),
      linear("risorius", 355.0f, at(1.05f, -1.15f), on(54), 0.18f, 0.1f),
      // From the mandible up to the corner and the lower lip; they ride the jaw.
      linear("depressor_anguli_oris", 220.0f, at(0.55f, -1.72f), on(54), 0.18f, 0.1f, 0.0f, true),
      linear("depressor_labii_inferioris", 129.0f, at(0.25f, -1.68f), on(56, 0.02f, 0.0f), 0.15f, 0.1f, 0.0f, true),
      // From the incisive fossa down into the chin's skin: raises the chin.
      linear("mentalis", 141.0f, at(0.1f, -1.4f), at(0.09f, -1.75f), 0.2f, 0.14f, 0.1f, true),
      // Half of the orbicularis oris, in its two parts: the peripheral part
      // narrows the mouth (AU 23), the marginal part in the red of the lips
      // presses them together (AU 24) and pulls their skin as fully as its
      // fascia, since no fat lies between them. (So pulled, the peripheral
      // part pressed the lips so hard that the projective face crept on
      // their contact for more than 10 s under AU 23.)
      sphincter("orbicularis_oris_peripheral", 67.0f, between(62, 66), {0.45f, 0.22f}, 0.75f, {1.0f, 0.5f, 0.15f},
                1.0f, true),
      in_the_lips(sphincter("orbicularis_oris_marginal", 83.0f, between(62, 66), {0.38f, 0.11f}, 0.8f,
                            {0.1f, 1.0f, 0.0f}, 1.0f, true)),
      // Jaw muscles: the masseter, from the zygomatic arch to the mandible's
      // angle, closes the jaw and bulges over the ramus as it contracts: by
      // ultrasound it is about 2 mm thicker clenched than relaxed (Raadsheer,
      // Kiliaridis, van Eijden, van Ginkel & Prahl-Andersen 1996; Kiliaridis
      // & Kalebo 1991: 1.5-2.5 mm); the digastric opens it (AU 26, 27).
      jaw("masseter", -0.05f, at(0.95f, -0.45f), at(0.97f, -1.3f), 0.2f, 2.0f),
      jaw("digastric", 0.42f, at(0.1f, -1.9f), at(0.2f, -1.9f), 0.1f),
  }};
}

}  // namespace

const std::array<MuscleDefinition, kMusclesPerSide>& facial_muscle_definitions() {
  static const std::array<MuscleDefinition, kMusclesPerSide> definitions = make_definitions();
  return definitions;
}

int muscle_index(std::string_view name, bool left) {
  const auto& defs = facial_muscle_definitions();
  for (std::size_t i = 0; i < defs.size(); ++i)
    if (defs[i].name == name) return static_cast<int>(2 * i + (left ? 0 : 1));
  return -1;
}

std::string muscle_name(std::size_t index) {
  assert(index < kMuscleCount);
  std::string name(facial_muscle_definitions()[index / 2].name);
  name += index % 2 == 0 ? "_left" : "_right";
  return name;
}

}  // namespace fw::physics
