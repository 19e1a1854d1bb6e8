#include "cli/Progress.h"

#include <cstdio>
#include <unistd.h>

namespace tetglow::cli {

Progress::Progress(std::string label)
    : label_(std::move(label)), terminal_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void Progress::update(double fraction) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (terminal_) {
        const int perMille = int(fraction * 1000);
        if (perMille == lastShown_) return;
        lastShown_ = perMille;
        constexpr int kWidth = 40;
        const int filled = int(fraction * kWidth);
        const double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
        std::fprintf(stderr, "\r%s [%.*s%*s] %5.1f%%  %.1f s, %.1f s left ", label_.c_str(), filled,
                     "########################################", kWidth - filled, "", 100 * fraction, elapsed, left);
    } else {
        const int tens = int(fraction * 10);
        if (tens == lastShown_) return;
        lastShown_ = tens;
        std::fprintf(stderr, "%s: %d%% after %.1f s\n", label_.c_str(), 10 * tens, elapsed);
    }
    std::fflush(stderr);
}

void Progress::finish() {
    if (terminal_ && lastShown_ >= 0) std::fputc('\n', stderr);
}

}  // namespace tetglow::cli
