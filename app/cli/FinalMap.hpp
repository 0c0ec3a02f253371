// `dynamap explore --final-map`: after a mission, its recording mapped again along the
// loop-closed trajectory into OUT/final_map/, and the figures of that map added to the
// mission's report.json. The mission's own map was built from the poses SLAM had while
// the robot drove; loop closure corrects them only afterwards.
#pragma once

#include <string>

namespace dynamap::app {

struct FinalMapRequest {
  std::string mission_dir;    // Holds trajectory.tum and report.json.
  std::string recording_dir;  // The mission's recording (or the one it replayed).
  std::string mapping_file;   // The mission's map settings; "" = defaults.
  std::string rig_file;       // The rig replacing the recorded one; "" = the recorded rig.
};

// Fails the command (as `dynamap map` does) when the recording or trajectory cannot be
// read; the mission's own results are already saved by then.
void BuildFinalMap(const FinalMapRequest& request);

}  // namespace dynamap::app
