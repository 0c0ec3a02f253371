// Shared pieces of the GUI test suites: the suites' factories, a small synthetic dual map
// (an office room with a desk and a walking person in the dynamic channel) and file paths.
#pragma once

#include <QObject>
#include <QString>
#include <memory>

#include "dynamap/mapping/DualOcTree.hpp"

namespace dynamap::app::gui::test {

std::unique_ptr<QObject> MakeVoxelSetTest();
std::unique_ptr<QObject> MakeMapsWorkspaceTest();
std::unique_ptr<QObject> MakeMainWindowTest();
std::unique_ptr<QObject> MakeMissionWorkspaceTest();
std::unique_ptr<QObject> MakeCalibrationWorkspaceTest();
std::unique_ptr<QObject> MakeScreenshotTest();

// An 8 m x 5 m room (floor, walls 2.4 m high, a partition with a door gap, a desk and a
// cabinet) in the static channel and a person seen at two places in the dynamic channel.
std::unique_ptr<mapping::DualOcTree> MakeOfficeScene();

// Leaf edge of MakeOfficeScene's tree, m.
constexpr double kResolution = 0.05;

// Saves MakeOfficeScene() as a dual .ot under `dir` and returns its path.
QString WriteOfficeScene(const QString& dir);

// ../shared/data/octomap/geb079.bt
QString Geb079Path();

// A directory in the build tree for test output (created).
QString OutputDir(const QString& name);

// `dynamap record` of the calibration room's scripted guided sequence, its first
// `seconds`, at 160 px, into the new folder `dir`; false (with a test warning) on failure.
bool RecordCalibrationRoom(const QString& dir, int seconds);

}  // namespace dynamap::app::gui::test
