// The most recently opened map files, newest first, kept in QSettings between sessions.
#pragma once

#include <QSettings>
#include <QString>
#include <QStringList>

namespace dynamap::app::gui {

class RecentFiles {
 public:
  static constexpr int kDefaultCapacity = 8;
  static constexpr const char* kSettingsKey = "recent_files";

  explicit RecentFiles(int capacity = kDefaultCapacity) : capacity_(capacity) {}

  void Load(const QSettings& settings);
  void Save(QSettings& settings) const;
  // Moves `file` (made absolute) to the front; drops the oldest beyond capacity.
  void Add(const QString& file);
  void Remove(const QString& file);
  [[nodiscard]] const QStringList& Files() const { return files_; }

 private:
  int capacity_;
  QStringList files_;
};

}  // namespace dynamap::app::gui
