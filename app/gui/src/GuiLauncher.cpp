#include "dynamap/app/gui/GuiLauncher.hpp"

#include <QApplication>
#include <QString>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "dynamap/app/Version.hpp"
#include "dynamap/app/gui/MainWindow.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"

namespace dynamap::app::gui {

bool DisplayAvailable() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && value[0] != '\0') return true;
  }
  return false;
}

void ApplyStartOptions(MainWindow& window, const GuiOptions& options) {
  if (!options.map_file.empty()) window.OpenMap(QString::fromStdString(options.map_file));
  if (!options.explore_world.empty()) {
    ExploreRequest request;
    request.world_file = QString::fromStdString(options.explore_world);
    request.out_dir = QString::fromStdString(options.explore_out);
    if (options.explore_max_time_s > 0.0) request.max_time_s = options.explore_max_time_s;
    for (const auto source : {runtime::PoseSource::kSlam, runtime::PoseSource::kOdometry,
                              runtime::PoseSource::kGroundTruth}) {
      if (options.explore_poses == runtime::ToString(source)) request.poses = source;
    }
    if (options.explore_kinect_width > 0) request.kinect_width = options.explore_kinect_width;
    window.Explore(request);  // A refusal or failure shows in the window like a pressed Start.
  }
}

int RunGui(int& argc, char** argv, const GuiOptions& options) {
  try {
    // VTK needs its OpenGL core profile before the first widget exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("dynamap"));
    QApplication::setApplicationName(QStringLiteral("dynamap"));
    QApplication::setApplicationVersion(QStringLiteral(DYNAMAP_VERSION_STRING));
    MainWindow window;
    window.show();
    ApplyStartOptions(window, options);
    return QApplication::exec();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dynamap gui: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace dynamap::app::gui
