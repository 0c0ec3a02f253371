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

namespace dynamap::app::gui {

bool DisplayAvailable() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && value[0] != '\0') return true;
  }
  return false;
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
    if (!options.map_file.empty()) window.OpenMap(QString::fromStdString(options.map_file));
    return QApplication::exec();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dynamap gui: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace dynamap::app::gui
