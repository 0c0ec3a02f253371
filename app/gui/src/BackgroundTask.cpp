#include "dynamap/app/gui/BackgroundTask.hpp"

#include <QMetaObject>
#include <algorithm>
#include <cmath>
#include <exception>

namespace dynamap::app::gui {

void BackgroundTask::Context::ReportProgress(double fraction, const QString& stage) const {
  const int percent = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 100.0));
  Deliver([owner = owner_, percent, stage] {
    if (owner) emit owner->ProgressChanged(percent, stage);
  });
}

void BackgroundTask::Context::Deliver(std::function<void()> on_gui_thread) const {
  BackgroundTask* owner = owner_.data();
  if (owner == nullptr) return;
  const std::uint64_t generation = generation_;
  const auto cancel = cancel_;
  // Queued to the owner's thread; Qt drops the call if the owner is gone by then.
  QMetaObject::invokeMethod(
      owner,
      [owner, generation, cancel, fn = std::move(on_gui_thread)] {
        if (owner->generation_ == generation && !cancel->load()) fn();
      },
      Qt::QueuedConnection);
}

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {}

BackgroundTask::~BackgroundTask() {
  if (cancel_) cancel_->store(true);
  for (const auto& thread : threads_) {
    if (thread) thread->wait();
  }
}

void BackgroundTask::Start(const QString& title, std::function<void(const Context&)> work) {
  if (cancel_) cancel_->store(true);
  ++generation_;
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  running_ = true;
  title_ = title;
  const Context context(this, generation_, cancel_);
  const std::uint64_t generation = generation_;
  QPointer<BackgroundTask> self(this);
  QThread* thread = QThread::create([context, work = std::move(work), generation, self] {
    QString error;
    try {
      work(context);
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    } catch (...) {
      error = QStringLiteral("unknown error");
    }
    if (BackgroundTask* owner = self.data()) {
      QMetaObject::invokeMethod(
          owner, [owner, generation, error] { owner->OnWorkReturned(generation, error); },
          Qt::QueuedConnection);
    }
  });
  connect(thread, &QThread::finished, thread, &QObject::deleteLater);
  threads_.erase(std::remove_if(threads_.begin(), threads_.end(),
                                [](const QPointer<QThread>& t) { return t.isNull(); }),
                 threads_.end());
  threads_.emplace_back(thread);
  thread->start();
  emit Started(title);
}

void BackgroundTask::Cancel() {
  if (!running_) return;
  cancel_->store(true);
  running_ = false;
  emit Finished(true, QString());
}

void BackgroundTask::OnWorkReturned(std::uint64_t generation, const QString& error) {
  // A cancelled or replaced run has already been reported as finished.
  if (generation != generation_ || !running_) return;
  running_ = false;
  emit Finished(false, error);
}

}  // namespace dynamap::app::gui
