#include "dynamap/app/gui/RecentFiles.hpp"

#include <QDir>
#include <QFileInfo>

namespace dynamap::app::gui {

void RecentFiles::Load(const QSettings& settings) {
  files_ = settings.value(kSettingsKey).toStringList();
  files_.removeAll(QString());
  files_.removeDuplicates();
  while (files_.size() > capacity_) files_.removeLast();
}

void RecentFiles::Save(QSettings& settings) const { settings.setValue(kSettingsKey, files_); }

void RecentFiles::Add(const QString& file) {
  const QString absolute = QDir::cleanPath(QFileInfo(file).absoluteFilePath());
  files_.removeAll(absolute);
  files_.prepend(absolute);
  while (files_.size() > capacity_) files_.removeLast();
}

void RecentFiles::Remove(const QString& file) {
  files_.removeAll(QDir::cleanPath(QFileInfo(file).absoluteFilePath()));
}

}  // namespace dynamap::app::gui
