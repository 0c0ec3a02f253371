#include "dynamap/app/gui/ResourceFiles.hpp"

#include <QDir>

namespace dynamap::app::gui {

QString ResourcePath(const QString& relative) {
  return QDir(QStringLiteral(DYNAMAP_RESOURCES_DIR)).filePath(relative);
}

QStringList ResourceFiles(const QString& folder) {
  const QDir dir(ResourcePath(folder));
  QStringList files;
  for (const QString& name : dir.entryList({QStringLiteral("*.yaml")}, QDir::Files, QDir::Name)) {
    files << dir.absoluteFilePath(name);
  }
  return files;
}

}  // namespace dynamap::app::gui
