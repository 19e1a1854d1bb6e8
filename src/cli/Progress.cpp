#include "cli/Progress.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/NumberText.h"
#include "render/AdaptiveSampling.h"
#include "scene/SceneDescription.h"

namespace tetglow::cli {

double passesForNoise(int passes, double noise, double target, double planned) {
    if (planned > 0) return planned;
    return std::max(std::ceil(passes * noise / target), double(kPilotPasses));
}

std::string passesInWords(double passes) {
    if (passes > kMaxSpp) return "more than " + std::to_string(kMaxSpp) + " passes (the most a render takes)";
    return "about " + std::to_string(int(passes)) + " passes";
}

Progress::Progress(std::string label, RenderPlan plan)
    : label_(std::move(label)), plan_(std::move(plan)), terminal_(isatty(STDERR_FILENO)) {
    if (!openEnded()) return;
    std::string stops;
    if (plan_.noiseTarget > 0) stops += numberText("at noise %g (estimated relative MSE), ", plan_.noiseTarget);
    if (plan_.timeLimit > 0) stops += numberText("after %g s, ", plan_.timeLimit);
    stops += "or after " + std::to_string(plan_.passes) + " passes (" + plan_.passesFrom + ")";
    std::fprintf(stderr, "%s: stops %s, whichever comes first\n", label_.c_str(), stops.c_str());
}

void Progress::line(const std::string& text) {
    std::fprintf(stderr, "%s%s: %s\n", terminal_ && shown_ ? "\n" : "", label_.c_str(), text.c_str());
    shown_ = false;
}

void Progress::pass(const PassReport& r) {
    // The time left to the nearest stop: the passes left at the mean pass time, the time limit,
    // and the passes the noise estimate says the target needs. Before the first estimate only
    // the cap and the time limit bound it.
    const double perPass = r.seconds / r.passes;
    double left = (plan_.passes - r.passes) * perPass;
    if (plan_.timeLimit > 0) left = std::min(left, std::max(0.0, plan_.timeLimit - r.seconds));
    const bool pending = plan_.noiseTarget > 0 && !r.noise;
    if (plan_.noiseTarget > 0 && r.noise) {
        const double needed = passesForNoise(r.passes, *r.noise, plan_.noiseTarget, r.neededPasses);
        left = std::min(left, std::max(0.0, needed - r.passes) * perPass);
        if (!warned_ && needed > plan_.passes) {
            warned_ = true;
            line("warning: by the estimate after pass " + std::to_string(r.passes) +
                 numberText(", the noise target %g needs ", plan_.noiseTarget) + passesInWords(needed) +
                 ", more than the cap of " + std::to_string(plan_.passes) + " (" + plan_.passesFrom +
                 "): the render stops at the cap" +
                 (needed <= kMaxSpp ? "; raise it with --spp " + std::to_string(int(needed)) : ""));
        }
    }
    const double fraction = std::clamp(r.seconds / (r.seconds + left), 1e-9, 1.0);
    const int tenth = pending ? 0 : int(fraction * 10);
    if (!terminal_ && tenth == lastTenth_) return;
    lastTenth_ = tenth;

    char noise[96] = "noise: from the second pass";
    if (r.noise)
        std::snprintf(noise, sizeof noise, "noise %.3g (relative MSE%s)", *r.noise,
                      plan_.biased ? ", variance only: not the photon bias" : "");
    const std::string of =
        plan_.passes > 0 ? (openEnded() ? " of at most " : " of ") + std::to_string(plan_.passes) : "";
    const bool bounded = plan_.passes < kMaxSpp || plan_.timeLimit > 0;
    const std::string remaining = !pending  ? numberText("%.1f s left", left)
                                  : bounded ? numberText("at most %.1f s left", left)
                                            : "time left: from the second pass";
    std::fprintf(stderr, "%s%s: pass %d%s, %.1f s, %s, %s%s", terminal_ ? "\r" : "", label_.c_str(), r.passes,
                 of.c_str(), r.seconds, remaining.c_str(), noise, terminal_ ? "   " : "\n");
    std::fflush(stderr);
    shown_ = true;
}

void Progress::work(const std::string& done, double fraction, double seconds) {
    fraction = std::clamp(fraction, 1e-9, 1.0);
    const int tenth = int(fraction * 10);
    if (!terminal_ && tenth == lastTenth_) return;
    lastTenth_ = tenth;
    std::fprintf(stderr, "%s%s: %s, %.1f s, %.1f s left%s", terminal_ ? "\r" : "", label_.c_str(), done.c_str(),
                 seconds, seconds * (1 - fraction) / fraction, terminal_ ? "   " : "\n");
    std::fflush(stderr);
    shown_ = true;
}

void Progress::finish() {
    if (terminal_ && shown_) std::fputc('\n', stderr);
    shown_ = false;
}

void Progress::finish(const RenderResult& result) {
    finish();
    if (!openEnded() || result.stop == RenderStop::Cancelled) return;
    const std::string passes = std::to_string(result.passes) + " passes";
    const std::string noise = result.noise ? numberText("noise %.3g", *result.noise) : "no noise estimate";
    const std::string target = numberText("the noise target %g", plan_.noiseTarget);
    std::string text;
    if (result.stop == RenderStop::Noise) {
        text = "reached " + target + " after " + passes + " (" + noise + ")";
    } else if (result.stop == RenderStop::Time) {
        text = numberText("stopped by the time limit of %g s", plan_.timeLimit) + " after " + passes;
        if (plan_.noiseTarget > 0) text += ", before " + target + " (" + noise + ")";
    } else {
        text = "stopped at the cap of " + passes + " (" + plan_.passesFrom + ")";
        if (plan_.noiseTarget > 0) {
            text += ", before " + target + " (" + noise + ")";
            if (result.noise) {
                const double needed =
                    passesForNoise(result.passes, *result.noise, plan_.noiseTarget, result.neededPasses);
                text += "; it needs " + passesInWords(needed) +
                        (needed <= kMaxSpp ? " (--spp " + std::to_string(int(needed)) + ")" : "");
            }
        } else {
            text += numberText(", before the time limit of %g s", plan_.timeLimit);
        }
    }
    std::fprintf(stderr, "%s: %s\n", label_.c_str(), text.c_str());
}

}  // namespace tetglow::cli
