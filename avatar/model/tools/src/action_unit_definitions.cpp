#include "action_unit_definitions.hpp"

namespace fw::facegen {
namespace {

using R = model::FaceRegion;

// Lip, corner and chin regions of both sides: the mouth moves as one.
const std::vector<R> kMouth = {R::upper_lip, R::lower_lip, R::mouth_corner_left, R::mouth_corner_right, R::chin};

}  // namespace

// Displacements are for intensity 1 (FACS "E"); 0.1 unit is about 6 mm.
// Handles are on the person's left (x > 0, landmarks 22-26, 42-47, 54...);
// the right-side channel mirrors them.
ActionUnitDefinition action_unit_definition(int au) {
  switch (au) {
    case 1:  // inner brow raiser (frontalis, pars medialis)
      return {{{22, {}, {0.0f, 0.13f, 0.0f}, 0.35f}, {23, {}, {0.0f, 0.09f, 0.0f}, 0.3f}},
              std::nullopt, {R::brow_left, R::forehead, R::upper_lid_left}, 0.45f};
    case 2:  // outer brow raiser (frontalis, pars lateralis)
      return {{{25, {}, {0.0f, 0.12f, 0.0f}, 0.35f}, {26, {}, {0.0f, 0.09f, 0.0f}, 0.3f}, {24, {}, {0.0f, 0.07f, 0.0f}, 0.3f}},
              std::nullopt, {R::brow_left, R::forehead, R::upper_lid_left, R::hairline}, 0.45f};
    case 4:  // brow lowerer (corrugator, depressor supercilii, procerus)
      return {{{22, {}, {-0.05f, -0.09f, 0.0f}, 0.3f}, {23, {}, {-0.03f, -0.07f, 0.0f}, 0.3f}, {24, {}, {0.0f, -0.04f, 0.0f}, 0.3f}},
              std::nullopt, {R::brow_left, R::forehead, R::upper_lid_left, R::nose}, 0.5f};
    case 5:  // upper lid raiser
      return {{{43, {}, {0.0f, 0.04f, 0.0f}, 0.12f}, {44, {}, {0.0f, 0.04f, 0.0f}, 0.12f}},
              std::nullopt, {R::upper_lid_left}, 1.0f};
    case 6:  // cheek raiser (orbicularis oculi, pars orbitalis)
      return {{{46, {}, {0.0f, 0.025f, 0.0f}, 0.1f}, {47, {}, {0.0f, 0.025f, 0.0f}, 0.1f},
               {-1, {0.6f, -0.42f}, {0.0f, 0.07f, 0.03f}, 0.3f}},
              std::nullopt, {R::lower_lid_left, R::cheek_left}, 1.0f};
    case 7:  // lid tightener (orbicularis oculi, pars palpebralis)
      return {{{46, {}, {0.0f, 0.035f, 0.0f}, 0.1f}, {47, {}, {0.0f, 0.035f, 0.0f}, 0.1f},
               {43, {}, {0.0f, -0.015f, 0.0f}, 0.1f}, {44, {}, {0.0f, -0.015f, 0.0f}, 0.1f}},
              std::nullopt, {R::lower_lid_left, R::upper_lid_left}, 1.0f};
    case 9:  // nose wrinkler (levator labii superioris alaeque nasi), midline
      return {{{31, {}, {0.0f, 0.05f, 0.0f}, 0.18f}, {35, {}, {0.0f, 0.05f, 0.0f}, 0.18f},
               {-1, {0.0f, -0.2f}, {0.0f, 0.025f, 0.0f}, 0.2f}, {51, {}, {0.0f, 0.035f, 0.0f}, 0.2f},
               {21, {}, {0.0f, -0.04f, 0.0f}, 0.15f}, {22, {}, {0.0f, -0.04f, 0.0f}, 0.15f}},
              std::nullopt, {R::nose, R::upper_lip, R::brow_left, R::brow_right, R::cheek_left, R::cheek_right}, 1.0f};
    case 10:  // upper lip raiser (levator labii superioris)
      return {{{52, {}, {0.0f, 0.07f, 0.01f}, 0.18f}, {53, {}, {0.0f, 0.05f, 0.0f}, 0.18f}, {63, {}, {0.0f, 0.06f, 0.0f}, 0.15f}},
              std::nullopt, {R::upper_lip, R::mouth_corner_left, R::cheek_left}, 1.0f};
    case 12:  // lip corner puller (zygomaticus major)
      return {{{54, {}, {0.08f, 0.09f, -0.02f}, 0.3f}, {64, {}, {0.07f, 0.08f, -0.02f}, 0.25f},
               {-1, {0.62f, -0.75f}, {0.03f, 0.05f, 0.02f}, 0.3f}},
              std::nullopt, {R::upper_lip, R::lower_lip, R::mouth_corner_left, R::cheek_left, R::jaw_left, R::chin}, 1.0f};
    case 14:  // dimpler (buccinator)
      return {{{54, {}, {0.03f, 0.0f, -0.04f}, 0.15f}, {64, {}, {0.03f, 0.0f, -0.04f}, 0.12f}},
              std::nullopt, {R::mouth_corner_left, R::upper_lip, R::lower_lip, R::cheek_left}, 1.0f};
    case 15:  // lip corner depressor (depressor anguli oris)
      return {{{54, {}, {0.0f, -0.08f, 0.0f}, 0.25f}, {64, {}, {0.0f, -0.07f, 0.0f}, 0.2f}, {55, {}, {0.0f, -0.03f, 0.0f}, 0.15f}},
              std::nullopt, {R::mouth_corner_left, R::upper_lip, R::lower_lip, R::jaw_left, R::chin}, 1.0f};
    case 17:  // chin raiser (mentalis), midline
      return {{{8, {}, {0.0f, 0.05f, 0.03f}, 0.35f}, {57, {}, {0.0f, 0.05f, 0.02f}, 0.25f},
               {66, {}, {0.0f, 0.015f, 0.01f}, 0.12f}},
              std::nullopt, {R::chin, R::lower_lip, R::jaw_left, R::jaw_right}, 1.0f};
    case 20:  // lip stretcher (risorius)
      return {{{54, {}, {0.08f, -0.02f, -0.01f}, 0.28f}, {64, {}, {0.07f, -0.02f, 0.0f}, 0.22f}},
              std::nullopt, {R::mouth_corner_left, R::upper_lip, R::lower_lip, R::cheek_left, R::jaw_left}, 1.0f};
    case 23:  // lip tightener (orbicularis oris), midline
      return {{{48, {}, {0.035f, 0.0f, 0.0f}, 0.15f}, {54, {}, {-0.035f, 0.0f, 0.0f}, 0.15f},
               {51, {}, {0.0f, -0.015f, 0.01f}, 0.15f}, {57, {}, {0.0f, 0.015f, 0.01f}, 0.15f}},
              std::nullopt, kMouth, 1.0f};
    case 24:  // lip pressor, midline: lips pressed, the red of the lips thinner
      return {{{51, {}, {0.0f, -0.025f, 0.0f}, 0.15f}, {57, {}, {0.0f, 0.025f, 0.0f}, 0.15f}},
              std::nullopt, kMouth, 1.0f};
    case 25:  // lips part, midline
      return {{{66, {}, {0.0f, -0.06f, 0.0f}, 0.2f}, {57, {}, {0.0f, -0.04f, 0.0f}, 0.2f},
               {62, {}, {0.0f, 0.015f, 0.0f}, 0.15f}},
              std::nullopt, kMouth, 1.0f};
    case 26: {  // jaw drop: the jaw turns about its hinge, about 12 degrees
      ActionUnitDefinition d{{}, JawRotation{0.2f}, {R::lower_lip, R::chin, R::jaw_left, R::jaw_right, R::mouth_corner_left,
                                                   R::mouth_corner_right, R::side_left, R::side_right}, 1.0f};
      return d;
    }
    case 27: {  // mouth stretch: the jaw wide open, corners drawn in
      ActionUnitDefinition d{{{54, {}, {-0.04f, -0.05f, 0.0f}, 0.2f}, {48, {}, {0.04f, -0.05f, 0.0f}, 0.2f}},
                             JawRotation{0.42f},
                             {R::lower_lip, R::chin, R::jaw_left, R::jaw_right, R::mouth_corner_left, R::mouth_corner_right,
                              R::side_left, R::side_right, R::upper_lip},
                             1.0f};
      return d;
    }
    default: return {};
  }
}

}  // namespace fw::facegen
