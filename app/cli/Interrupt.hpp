// Ctrl-C (SIGINT) and SIGTERM during long commands: while an InterruptGuard lives, the
// first one only raises a flag, so the command can stop cleanly (a recording closes its
// files, a mission saves its maps and report); a second one ends the process as usual.
#pragma once

#include <atomic>
#include <csignal>

namespace dynamap::app {

class InterruptGuard {
 public:
  InterruptGuard();   // Clears the flag and routes both signals to it.
  ~InterruptGuard();  // Restores the previous handlers.
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Raised by the first signal. A signal handler can reach nothing but a lock-free global,
  // so this is the one place the CLI keeps one.
  [[nodiscard]] static std::atomic<bool>& flag();
  [[nodiscard]] static bool requested() { return flag().load(); }

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace dynamap::app
