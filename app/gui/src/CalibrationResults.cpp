#include "dynamap/app/gui/CalibrationResults.hpp"

#include "dynamap/app/gui/RigView.hpp"

#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <optional>

namespace dynamap::app::gui {

namespace cal = calibration;

namespace {

constexpr double kDeg = 180.0 / M_PI;

QString Format(double value, const std::string& unit) {
  if (unit == "rad") return QStringLiteral("%1°").arg(value * kDeg, 0, 'f', 3);
  if (unit == "m") return QStringLiteral("%1 mm").arg(value * 1000.0, 0, 'f', 1);
  if (unit == "s") return QStringLiteral("%1 ms").arg(value * 1000.0, 0, 'f', 1);
  return QStringLiteral("%1").arg(value, 0, 'f', 5);
}

QColor StatusColour(cal::Observability status) {
  switch (status) {
    case cal::Observability::kCalibrated:
      return QColor(200, 240, 200);
    case cal::Observability::kWeak:
      return QColor(250, 235, 180);
    case cal::Observability::kNotObservable:
      break;
  }
  return QColor(245, 200, 200);
}

}  // namespace

CalibrationResults::CalibrationResults(QWidget* parent) : QWidget(parent) {
  summary_ = new QLabel;
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  table_ = new QTableWidget(0, 6);
  table_->setHorizontalHeaderLabels({tr("Parameter"), tr("Estimate"), tr("± std dev"),
                                     tr("Status"), tr("Guess"), tr("Error to truth")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  plots_ = new QTabWidget;
  rig_view_ = new RigView;
  auto* tabs = new QTabWidget;
  tabs_ = tabs;
  auto* rig_page = new QWidget;
  auto* rig_layout = new QVBoxLayout(rig_page);
  rig_layout->addWidget(summary_);
  rig_layout->addWidget(table_, 1);
  tabs->addTab(rig_page, tr("Estimated rig"));
  tabs->addTab(rig_view_, tr("Rig in 3D"));
  tabs->addTab(plots_, tr("Residuals"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(tabs);
  Clear();
}

void CalibrationResults::Clear() {
  summary_->setText(tr("Solve to see the estimated rig, its uncertainties and the residuals."));
  table_->setRowCount(0);
  rig_view_->Clear();
  while (plots_->count() > 0) plots_->widget(0)->deleteLater(), plots_->removeTab(0);
}

void CalibrationResults::ShowRigTab() { tabs_->setCurrentWidget(rig_view_); }

void CalibrationResults::Show(const cal::SolverResult& result, const robotio::Rig& guess,
                              const robotio::Rig& truth, double true_scale_left,
                              double true_scale_right, double robot_radius_m) {
  rig_view_->ShowRig(result, guess, truth, robot_radius_m);
  QString summary = result.converged ? tr("<b>Solver converged.</b> ") : tr("<b>Solver failed.</b> ");
  summary += result.AllCalibrated() ? tr("Every parameter is calibrated.")
                                    : tr("Not every parameter is calibrated; Save needs "
                                         "\"save uncalibrated\".");
  summary += tr(" Cross-check of the Kinects: %1 pairs, %2° / %3 mm RMS.")
                 .arg(result.cross_check_pairs)
                 .arg(result.cross_check_rotation_rms_deg, 0, 'f', 3)
                 .arg(result.cross_check_translation_rms_m * 1000.0, 0, 'f', 1);
  for (const std::string& warning : result.warnings) {
    summary += QStringLiteral("<br>• ") + QString::fromStdString(warning).toHtmlEscaped();
  }
  summary_->setText(summary);

  std::vector<std::pair<const cal::ParameterEstimate*, std::optional<double>>> rows;
  for (std::size_t k = 0; k < result.kinects.size(); ++k) {
    const bool known = k < truth.kinects.size();
    Eigen::Vector3d rpy = Eigen::Vector3d::Zero(), t = Eigen::Vector3d::Zero();
    if (known) {
      rpy = robotio::MountRollPitchYaw(truth.kinects[k].T_base_kinect);
      t = truth.kinects[k].T_base_kinect.translation();
    }
    for (int i = 0; i < cal::kKinectParameterCount; ++i) {
      std::optional<double> value;
      if (known) value = i < 3 ? rpy[i] : i < 6 ? t[i - 3] : truth.kinects[k].latency_s;
      rows.emplace_back(&result.kinects[k].parameters[i], value);
    }
  }
  const bool known = !truth.kinects.empty();
  rows.emplace_back(&result.scale_left, known ? std::optional(true_scale_left) : std::nullopt);
  rows.emplace_back(&result.scale_right, known ? std::optional(true_scale_right) : std::nullopt);

  table_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const cal::ParameterEstimate& p = *rows[r].first;
    QString error = QStringLiteral("–");
    if (rows[r].second) {
      double e = p.estimate - *rows[r].second;
      if (p.unit == "rad") e = std::remainder(e, 2.0 * M_PI);
      error = Format(e, p.unit);
    }
    const QStringList cells = {QString::fromStdString(p.name), Format(p.estimate, p.unit),
                               Format(p.std_dev, p.unit),
                               QString::fromLatin1(cal::ObservabilityName(p.status)),
                               Format(p.guess, p.unit), error};
    for (int c = 0; c < cells.size(); ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (c == 3) {
        item->setBackground(StatusColour(p.status));
        item->setToolTip(QString::fromStdString(p.reason));
      }
      table_->setItem(r, c, item);
    }
  }
}

void CalibrationResults::ShowPlots(const std::vector<std::string>& files) {
  while (plots_->count() > 0) plots_->widget(0)->deleteLater(), plots_->removeTab(0);
  for (const std::string& file : files) {
    const QPixmap pixmap(QString::fromStdString(file));
    if (pixmap.isNull()) continue;
    auto* label = new QLabel;
    label->setPixmap(pixmap);
    auto* scroll = new QScrollArea;
    scroll->setWidget(label);
    const QString name = QFileInfo(QString::fromStdString(file)).baseName();
    plots_->addTab(scroll, QString(name).remove(QStringLiteral("residuals_")));
  }
}

int CalibrationResults::PlotCount() const { return plots_->count(); }

}  // namespace dynamap::app::gui
