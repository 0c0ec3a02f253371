// bench_gui_rotation MAP [FRAMES]: opens MAP in the Maps workspace at 1280x800, rotates
// the camera one degree per frame as a drag does (the view draws points while dragging)
// and prints JSON: voxels drawn, median / p95 / max ms per dragging frame, and the median
// of the full cube frame drawn when the drag ends.
#include <QApplication>
#include <QElapsedTimer>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindow.h>
#include <QtTest/QTest>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dynamap/app/gui/MapsWorkspace.hpp"
#include "dynamap/app/gui/VoxelView.hpp"

int main(int argc, char** argv) {
  using namespace dynamap::app::gui;
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_gui_rotation MAP [FRAMES]\n");
    return 2;
  }
  const int frames = argc > 2 ? std::max(10, std::atoi(argv[2])) : 360;
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  MapsWorkspace workspace;
  workspace.resize(1280, 800);
  workspace.show();
  if (!QTest::qWaitForWindowExposed(&workspace)) return 1;
  QElapsedTimer load_timer;
  load_timer.start();
  workspace.OpenFile(QString::fromLocal8Bit(argv[1]));
  while (workspace.Busy()) QTest::qWait(20);
  const double load_s = load_timer.elapsed() / 1000.0;
  if (!workspace.Map()) {
    std::fprintf(stderr, "bench_gui_rotation: %s\n", qPrintable(workspace.LastError()));
    return 1;
  }
  VoxelView* view = workspace.View();
  const auto time_frames = [view](int count) {
    std::vector<double> ms;
    for (int i = 0; i < count; ++i) {
      const auto start = std::chrono::steady_clock::now();
      view->RotateAndRender(1.0);
      // Wait for the GPU (glFinish): otherwise only the time to queue commands counts.
      view->renderWindow()->WaitForCompletion();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                             start).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms;
  };
  const auto at = [](const std::vector<double>& ms, double q) {
    return ms[static_cast<std::size_t>(q * static_cast<double>(ms.size() - 1))];
  };
  view->SetInteracting(true);
  time_frames(10);  // Warm-up: buffer uploads and shader compiles.
  const auto dragging = time_frames(frames);
  view->SetInteracting(false);
  time_frames(2);
  const auto still = time_frames(5);
  std::printf(
      "{\"map\": \"%s\", \"voxels_drawn\": %zu, \"load_s\": %.2f, \"frames\": %d, "
      "\"dragging_median_ms\": %.2f, \"dragging_p95_ms\": %.2f, \"dragging_max_ms\": %.2f, "
      "\"cubes_median_ms\": %.1f}\n",
      argv[1],
      view->VisibleCount(VoxelLayer::kStatic) + view->VisibleCount(VoxelLayer::kDynamic),
      load_s, frames, at(dragging, 0.5), at(dragging, 0.95), dragging.back(), at(still, 0.5));
  return 0;
}
