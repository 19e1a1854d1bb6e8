// Ctrl-C (SIGINT), and SIGTERM and SIGHUP (what Slurm's scancel and time limits send, and a
// closed terminal), while an InterruptGuard lives: the first sets interrupted(), so that a render
// stops after the tiles in flight and its image is still written, whole; a second ends the
// process at once, removing the temporary of any write in progress (removeTemporaries).
#pragma once
#include <atomic>
#include <csignal>

namespace tetglow::cli {

class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    struct sigaction previous_[3];
};

// Set by the first signal.
const std::atomic<bool>& interrupted();
// The first signal's number (0 when none came); a command it stopped exits 128 + it.
int interruptSignal();
// "SIGINT", "SIGTERM" or "SIGHUP".
const char* interruptName();

}  // namespace tetglow::cli
