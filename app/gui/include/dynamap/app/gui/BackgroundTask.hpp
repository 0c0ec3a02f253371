// Runs one piece of long work (loading a map, exporting) off the GUI thread with progress
// and cancel, and hands its result back on the GUI thread through a queued call, so the
// window never freezes and no exception crosses the thread boundary.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>
#include <QThread>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace dynamap::app::gui {

class BackgroundTask : public QObject {
  Q_OBJECT

 public:
  // What the work function sees on its own thread.
  class Context {
   public:
    [[nodiscard]] bool Cancelled() const { return cancel_->load(); }
    [[nodiscard]] const std::atomic<bool>& CancelFlag() const { return *cancel_; }
    // fraction in [0, 1]; shown on the GUI thread by the ProgressChanged signal.
    void ReportProgress(double fraction, const QString& stage) const;
    // Runs `on_gui_thread` later on the GUI thread unless the task was cancelled or
    // replaced by then; the one way results travel back.
    void Deliver(std::function<void()> on_gui_thread) const;

   private:
    friend class BackgroundTask;
    Context(BackgroundTask* owner, std::uint64_t generation,
            std::shared_ptr<std::atomic<bool>> cancel)
        : owner_(owner), generation_(generation), cancel_(std::move(cancel)) {}
    QPointer<BackgroundTask> owner_;
    std::uint64_t generation_;
    std::shared_ptr<std::atomic<bool>> cancel_;
  };

  explicit BackgroundTask(QObject* parent = nullptr);
  // Cancels and waits for the work still running, so nothing outlives the owner.
  ~BackgroundTask() override;

  // Starts `work` on a new thread, cancelling the task that runs now (its results are
  // dropped). `title` names the work in the progress display.
  void Start(const QString& title, std::function<void(const Context&)> work);
  // Returns at once; the work stops at its next cancellation point.
  void Cancel();
  [[nodiscard]] bool Running() const { return running_; }
  [[nodiscard]] const QString& Title() const { return title_; }

 signals:
  void Started(const QString& title);
  void ProgressChanged(int percent, const QString& stage);
  // The work returned, threw, or was cancelled; `error` is empty unless it threw.
  void Finished(bool cancelled, const QString& error);

 private:
  void OnWorkReturned(std::uint64_t generation, const QString& error);

  std::uint64_t generation_ = 0;
  std::shared_ptr<std::atomic<bool>> cancel_;
  std::vector<QPointer<QThread>> threads_;
  bool running_ = false;
  QString title_;
};

}  // namespace dynamap::app::gui
