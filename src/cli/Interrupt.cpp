#include "cli/Interrupt.h"

#include "base/OutputFile.h"

namespace tetglow::cli {
namespace {

const int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
std::atomic<bool> interruptedFlag{false};
volatile std::sig_atomic_t firstSignal = 0;

void onSignal(int signal) {
    if (!interruptedFlag.exchange(true)) {
        firstSignal = signal;
        return;
    }
    removeTemporaries();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

InterruptGuard::InterruptGuard() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &previous_[i]);
}

InterruptGuard::~InterruptGuard() {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
}

const std::atomic<bool>& interrupted() { return interruptedFlag; }

int interruptSignal() { return firstSignal; }

const char* interruptName() {
    switch (firstSignal) {
        case SIGTERM: return "SIGTERM";
        case SIGHUP: return "SIGHUP";
        default: return "SIGINT";
    }
}

}  // namespace tetglow::cli
