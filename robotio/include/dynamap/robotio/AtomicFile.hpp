// Files are written atomically: to a temporary file beside the target, then renamed,
// so a crash never leaves a half-written map, rig or report.
#pragma once

#include <functional>
#include <string>

#include "dynamap/robotio/Expected.hpp"

namespace dynamap::robotio {

[[nodiscard]] Status WriteFileAtomically(const std::string& file, const std::string& contents);

// For writers that need a path (OpenCV, OctoMap): `write` gets the temporary path and
// returns false on failure; on success the temporary file is renamed to `file`.
[[nodiscard]] Status WriteFileAtomically(const std::string& file,
                                         const std::function<bool(const std::string&)>& write);

// A temporary path in the same directory as `file` (same filesystem, so rename is atomic).
[[nodiscard]] std::string TemporaryPathFor(const std::string& file);

}  // namespace dynamap::robotio
