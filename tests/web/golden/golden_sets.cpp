// The list of the browser's golden files: a new port's file is added here,
// and the writer program and the C++ test pick it up.
#include "golden_json.hpp"
#include "mute_list_golden.hpp"
#include "package_assembly_golden.hpp"
#include "reconnect_policy_golden.hpp"
#include "seat_frames_golden.hpp"

namespace fw::test::web_golden {

const std::vector<GoldenSet>& golden_sets() {
  static const std::vector<GoldenSet> sets = {
      {"reconnect_policy", reconnect_policy_golden},
      {"seat_frames", seat_frames_golden},
      {"mute_list", mute_list_golden},
      {"package_assembly", package_assembly_golden},
  };
  return sets;
}

}  // namespace fw::test::web_golden
