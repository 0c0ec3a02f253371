#include "dynamap/app/gui/MapsWorkspace.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QVBoxLayout>

#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/VoxelView.hpp"
#include "dynamap/mapping/MapFiles.hpp"

namespace dynamap::app::gui {

namespace {

// The tree type line of an .ot header sits in its first few lines; reading 512 bytes
// tells a dual map from a plain OctoMap without parsing the file twice.
bool IsDualMapFile(const QString& file) {
  QFile f(file);
  if (!f.open(QIODevice::ReadOnly)) return false;
  const QByteArray head = f.read(512);
  return head.contains(QByteArray("id ") + mapping::DualOcTree::kTreeType);
}

}  // namespace

MapsWorkspace::MapsWorkspace(QWidget* parent) : QWidget(parent) {
  controls_ = new MapControls;
  view_ = new VoxelView;
  task_ = new BackgroundTask(this);

  auto* scroll = new QScrollArea;
  scroll->setWidget(controls_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setMinimumWidth(270);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->setObjectName(QStringLiteral("maps_splitter"));
  splitter->addWidget(scroll);
  splitter->addWidget(view_);
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({290, 1000});

  progress_strip_ = new QWidget;
  auto* strip_layout = new QHBoxLayout(progress_strip_);
  strip_layout->setContentsMargins(6, 2, 6, 2);
  progress_label_ = new QLabel;
  progress_bar_ = new QProgressBar;
  cancel_button_ = new QPushButton(tr("Cancel"));
  cancel_button_->setShortcut(Qt::Key_Escape);
  strip_layout->addWidget(progress_label_);
  strip_layout->addWidget(progress_bar_, 1);
  strip_layout->addWidget(cancel_button_);
  progress_strip_->hide();

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(splitter, 1);
  layout->addWidget(progress_strip_);

  connect(controls_, &MapControls::FilterChanged, this, &MapsWorkspace::OnFilterChanged);
  connect(controls_, &MapControls::ColourModeChanged, this, &MapsWorkspace::OnColourModeChanged);
  connect(view_, &VoxelView::VoxelPicked, this, [this](const std::optional<VoxelPick>& pick) {
    controls_->ShowPick(pick, map_ ? map_->voxels.get() : nullptr);
  });
  connect(cancel_button_, &QPushButton::clicked, this, &MapsWorkspace::CancelWork);
  connect(task_, &BackgroundTask::ProgressChanged, this, &MapsWorkspace::OnTaskProgress);
  connect(task_, &BackgroundTask::Finished, this, &MapsWorkspace::OnTaskFinished);
}

MapsWorkspace::~MapsWorkspace() = default;

void MapsWorkspace::OpenFile(const QString& file) {
  if (!QFileInfo(file).isFile()) {
    // Named as given, so the operator recognises what they typed or clicked.
    Fail(tr("Cannot open map %1: no such file.").arg(file));
    return;
  }
  const bool dual = IsDualMapFile(file);
  progress_label_->setText(tr("Loading %1").arg(QFileInfo(file).fileName()));
  progress_bar_->setRange(0, 0);  // Reading has no progress of its own: busy indicator.
  progress_strip_->show();
  emit BusyChanged(true);
  task_->Start(tr("Loading map"), [this, file, dual](const BackgroundTask::Context& context) {
    auto loaded = mapping::LoadMap(file.toStdString());
    if (!loaded.ok()) {
      const QString message = QString::fromStdString(loaded.error().message);
      context.Deliver([this, message] { Fail(message); });
      return;
    }
    if (context.Cancelled()) return;
    context.ReportProgress(0.0, tr("Collecting voxels"));
    auto voxels = ExtractVoxels(**loaded, context.CancelFlag(), [&context](double fraction) {
      context.ReportProgress(fraction, tr("Collecting voxels"));
    });
    if (!voxels) return;
    auto map = std::make_shared<LoadedMap>();
    map->file = QDir::cleanPath(QFileInfo(file).absoluteFilePath());
    map->tree = std::move(loaded).value();
    map->voxels = std::make_shared<const VoxelSet>(std::move(*voxels));
    map->dual = dual;
    context.Deliver([this, map = std::shared_ptr<const LoadedMap>(map)] { ShowMap(map); });
  });
}

void MapsWorkspace::Export(ExportKind kind, const QString& file) {
  if (!map_) {
    Fail(tr("Cannot export to %1: no map is open.").arg(file));
    return;
  }
  progress_label_->setText(tr("Writing %1").arg(QFileInfo(file).fileName()));
  progress_bar_->setRange(0, 0);
  progress_strip_->show();
  emit BusyChanged(true);
  task_->Start(tr("Exporting"), [this, kind, file, map = map_](const BackgroundTask::Context& c) {
    const auto status = ExportMap(*map->tree, kind, file.toStdString());
    if (status.ok()) {
      c.Deliver([this, file] {
        emit StatusMessage(tr("Wrote %1").arg(file));
        emit ExportFinished(file);
      });
    } else {
      const QString message = QString::fromStdString(status.error().message);
      c.Deliver([this, message] { Fail(message); });
    }
  });
}

bool MapsWorkspace::SaveViewImage(const QString& file) {
  const QImage image = view_->grabFramebuffer();
  if (image.isNull() || !image.save(file, "PNG")) {
    Fail(tr("Cannot write the view image %1: the file could not be written as PNG.").arg(file));
    return false;
  }
  emit StatusMessage(tr("Wrote %1").arg(file));
  return true;
}

void MapsWorkspace::CancelWork() { task_->Cancel(); }

bool MapsWorkspace::Busy() const { return task_->Running(); }

void MapsWorkspace::ShowMap(std::shared_ptr<const LoadedMap> map) {
  map_ = std::move(map);
  last_error_.clear();
  controls_->SetMap(map_->file, map_->voxels.get(), map_->dual);
  view_->SetVoxels(map_->voxels, controls_->Filter(), controls_->Colours(), true);
  controls_->SetVisibleCounts(view_->VisibleCount(VoxelLayer::kStatic),
                              view_->VisibleCount(VoxelLayer::kDynamic));
  emit StatusMessage(tr("Opened %1: %2 voxels")
                         .arg(map_->file)
                         .arg(map_->voxels->voxels.size()));
  emit MapOpened(map_->file);
}

void MapsWorkspace::Fail(const QString& message) {
  last_error_ = message;
  emit StatusMessage(message);
  emit ErrorOccurred(message);
}

void MapsWorkspace::OnFilterChanged() {
  view_->SetFilter(controls_->Filter());
  controls_->SetVisibleCounts(view_->VisibleCount(VoxelLayer::kStatic),
                              view_->VisibleCount(VoxelLayer::kDynamic));
}

void MapsWorkspace::OnColourModeChanged() { view_->SetColourMode(controls_->Colours()); }

void MapsWorkspace::OnTaskProgress(int percent, const QString& stage) {
  progress_bar_->setRange(0, 100);
  progress_bar_->setValue(percent);
  progress_bar_->setFormat(stage + QStringLiteral(" %p%"));
}

void MapsWorkspace::OnTaskFinished(bool cancelled, const QString& error) {
  progress_strip_->hide();
  if (cancelled) emit StatusMessage(tr("%1 cancelled").arg(task_->Title()));
  if (!error.isEmpty()) Fail(tr("%1 failed: %2").arg(task_->Title(), error));
  emit BusyChanged(false);
}

}  // namespace dynamap::app::gui
