#include "fw/behavior/articulation.hpp"

namespace fw::behavior {

void articulate(AuTargets& au, const AuTargets& mouth) {
  for (std::size_t c = 0; c < codec::kAuChannels.size(); ++c)
    for (const int articulated : kArticulationAus)
      if (codec::kAuChannels[c].au == articulated) au[c] = mouth[c];
}

AuTargets without_articulation(AuTargets au) {
  articulate(au, AuTargets{});
  return au;
}

}  // namespace fw::behavior
