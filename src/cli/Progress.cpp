#include "cli/Progress.h"

#include <unistd.h>
#include <algorithm>
#include <cstdio>

namespace tetglow::cli {

Progress::Progress(std::string label, RenderPlan plan)
    : label_(std::move(label)), plan_(plan), terminal_(isatty(STDERR_FILENO)) {}

void Progress::pass(const PassReport& r) {
    // The part of the way done, by whichever limit is nearest. The noise falls as 1/passes, so
    // the passes done are target/estimate of the passes needed.
    double fraction = plan_.passes > 0 ? double(r.passes) / plan_.passes : 0;
    if (plan_.timeLimit > 0) fraction = std::max(fraction, r.seconds / plan_.timeLimit);
    if (plan_.noiseTarget > 0 && r.noise && *r.noise > 0) fraction = std::max(fraction, plan_.noiseTarget / *r.noise);
    char noise[96] = "noise: from the second pass";
    if (r.noise)
        std::snprintf(noise, sizeof noise, "noise %.3g (relative MSE%s)", *r.noise,
                      plan_.biased ? ", variance only: not the photon bias" : "");
    const bool counted = plan_.passes > 0 && plan_.timeLimit == 0 && plan_.noiseTarget == 0;
    show("pass " + std::to_string(r.passes) + (counted ? " of " + std::to_string(plan_.passes) : ""), fraction,
         r.seconds, std::string(", ") + noise);
}

void Progress::work(const std::string& done, double fraction, double seconds) { show(done, fraction, seconds, ""); }

void Progress::show(const std::string& done, double fraction, double seconds, const std::string& tail) {
    fraction = std::clamp(fraction, 1e-9, 1.0);
    const int tenth = int(fraction * 10);
    if (!terminal_ && tenth == lastTenth_) return;
    lastTenth_ = tenth;
    std::fprintf(stderr, "%s%s: %s, %.1f s, %.1f s left%s%s", terminal_ ? "\r" : "", label_.c_str(), done.c_str(),
                 seconds, seconds * (1 - fraction) / fraction, tail.c_str(), terminal_ ? "   " : "\n");
    std::fflush(stderr);
    shown_ = true;
}

void Progress::finish() {
    if (terminal_ && shown_) std::fputc('\n', stderr);
}

}  // namespace tetglow::cli
