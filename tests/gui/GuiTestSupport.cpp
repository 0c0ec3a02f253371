#include "GuiTestSupport.hpp"

#include <QDir>
#include <QProcess>
#include <octomap/octomap_utils.h>

#include <cmath>

#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/mapping/MapFiles.hpp"

namespace dynamap::app::gui::test {

namespace {

const float kFreeLogOdds = octomap::logodds(0.1192);

void FillBox(mapping::DualOcTree& tree, float x0, float y0, float z0, float x1, float y1,
             float z1) {
  const auto step = static_cast<float>(kResolution);
  for (float x = x0; x < x1; x += step) {
    for (float y = y0; y < y1; y += step) {
      for (float z = z0; z < z1; z += step) {
        // New nodes start with dynamic log-odds 0 (= p 0.5, "occupied"); the mapper starts
        // them at the lower clamp, and so does this scene.
        tree.updateNode(octomap::point3d(x, y, z), true, true)->SetDynamicLogOdds(kFreeLogOdds);
      }
    }
  }
}

void AddPerson(mapping::DualOcTree& tree, float cx, float cy, float probability) {
  const auto step = static_cast<float>(kResolution);
  const float dynamic = octomap::logodds(probability);
  for (float z = 0.05f; z < 1.75f; z += step) {
    // Narrower head and shoulders than body, so the shape reads as a person.
    const float radius = z > 1.5f ? 0.11f : (z > 1.35f ? 0.2f : 0.17f);
    for (float x = cx - radius; x <= cx + radius; x += step) {
      for (float y = cy - radius; y <= cy + radius; y += step) {
        if (std::hypot(x - cx, y - cy) > radius) continue;
        auto* node = tree.updateNode(octomap::point3d(x, y, z), false, true);
        node->SetDynamicLogOdds(dynamic);
      }
    }
  }
}

}  // namespace

std::unique_ptr<mapping::DualOcTree> MakeOfficeScene() {
  auto tree = std::make_unique<mapping::DualOcTree>(kResolution);
  const float h = 2.4f;
  FillBox(*tree, 0.0f, 0.0f, 0.0f, 8.0f, 5.0f, 0.05f);     // floor
  FillBox(*tree, 0.0f, 0.0f, 0.05f, 8.0f, 0.1f, h);        // south wall
  FillBox(*tree, 0.0f, 4.9f, 0.05f, 8.0f, 5.0f, h);        // north wall
  FillBox(*tree, 0.0f, 0.1f, 0.05f, 0.1f, 4.9f, h);        // west wall
  FillBox(*tree, 7.9f, 0.1f, 0.05f, 8.0f, 4.9f, h);        // east wall
  FillBox(*tree, 5.0f, 0.1f, 0.05f, 5.1f, 2.6f, h);        // partition ...
  FillBox(*tree, 5.0f, 3.5f, 0.05f, 5.1f, 4.9f, h);        // ... with a door gap
  FillBox(*tree, 1.0f, 3.6f, 0.70f, 2.6f, 4.4f, 0.75f);    // desk top
  for (const float x : {1.05f, 2.5f}) {
    for (const float y : {3.65f, 4.3f}) FillBox(*tree, x, y, 0.05f, x + 0.05f, y + 0.05f, 0.7f);
  }
  FillBox(*tree, 6.2f, 4.3f, 0.05f, 7.8f, 4.85f, 1.9f);    // cabinet
  AddPerson(*tree, 3.0f, 2.0f, 0.9f);
  AddPerson(*tree, 4.1f, 1.2f, 0.7f);  // where the same person was a moment earlier
  tree->updateInnerOccupancy();
  tree->prune();
  return tree;
}

QString WriteOfficeScene(const QString& dir) {
  const QString file = QDir(dir).filePath(QStringLiteral("office_scene.ot"));
  const auto status = mapping::SaveDualMap(*MakeOfficeScene(), file.toStdString());
  return status.ok() ? file : QString();
}

QString Geb079Path() {
  return QDir(QStringLiteral(DYNAMAP_SHARED_DATA_DIR)).filePath(QStringLiteral("octomap/geb079.bt"));
}

QString OutputDir(const QString& name) {
  const QString dir = QDir(QStringLiteral(DYNAMAP_BINARY_DIR)).filePath(name);
  QDir().mkpath(dir);
  return dir;
}

bool RecordCalibrationRoom(const QString& dir, int seconds) {
  QProcess record;
  record.setProcessChannelMode(QProcess::MergedChannels);
  record.start(QString::fromUtf8(DYNAMAP_EXECUTABLE),
               {QStringLiteral("record"), QStringLiteral("--world"),
                ResourcePath(QStringLiteral("worlds/calibration_room.yaml")),
                QStringLiteral("--duration"), QString::number(seconds), QStringLiteral("--width"),
                QStringLiteral("160"), QStringLiteral("--out"), dir});
  const bool finished = record.waitForFinished(180000);
  if (!finished || record.exitCode() != 0) {
    qWarning("dynamap record failed: %s", record.readAll().constData());
    return false;
  }
  return true;
}

}  // namespace dynamap::app::gui::test
