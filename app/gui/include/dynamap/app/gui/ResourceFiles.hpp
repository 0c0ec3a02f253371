// The files shipped in the source tree's resources/ folder (worlds, rigs, robots), which
// the workspaces offer in their choosers; dynamap runs from its build tree.
#pragma once

#include <QString>
#include <QStringList>

namespace dynamap::app::gui {

// Absolute path of resources/<relative>.
[[nodiscard]] QString ResourcePath(const QString& relative);
// The *.yaml files of resources/<folder>, sorted by name, absolute paths.
[[nodiscard]] QStringList ResourceFiles(const QString& folder);

}  // namespace dynamap::app::gui
