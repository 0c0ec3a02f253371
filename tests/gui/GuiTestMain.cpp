// Runs the GUI test suites: all of them, or the one named by the first argument (ctest
// registers one entry per suite). Settings go to a temporary directory, never the user's.
#include <QApplication>
#include <QByteArray>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "GuiTestSupport.hpp"

int main(int argc, char** argv) {
  using namespace dynamap::app::gui::test;
  QTemporaryDir config_dir;
  qputenv("XDG_CONFIG_HOME", config_dir.path().toLocal8Bit());
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("dynamap-test"));
  QApplication::setApplicationName(QStringLiteral("test_gui"));

  const std::vector<std::pair<const char*, std::function<std::unique_ptr<QObject>()>>> suites = {
      {"VoxelSetTest", MakeVoxelSetTest},
      {"MapsWorkspaceTest", MakeMapsWorkspaceTest},
      {"MainWindowTest", MakeMainWindowTest},
      {"MissionWorkspaceTest", MakeMissionWorkspaceTest},
      {"CalibrationWorkspaceTest", MakeCalibrationWorkspaceTest},
      {"ScreenshotTest", MakeScreenshotTest},
  };
  // argv[1] may name one suite; the remaining arguments go to QTest.
  const char* only = nullptr;
  std::vector<char*> qtest_args = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    bool is_suite = false;
    for (const auto& suite : suites) is_suite |= std::strcmp(argv[i], suite.first) == 0;
    if (i == 1 && is_suite) {
      only = argv[i];
    } else {
      qtest_args.push_back(argv[i]);
    }
  }
  int failures = 0;
  for (const auto& [name, make] : suites) {
    if (only != nullptr && std::strcmp(only, name) != 0) continue;
    const auto suite = make();
    failures += QTest::qExec(suite.get(), static_cast<int>(qtest_args.size()), qtest_args.data());
  }
  return failures == 0 ? 0 : 1;
}
