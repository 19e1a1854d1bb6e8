#include "tet/RepairClock.h"

#include <algorithm>
#include <cstdio>

namespace tetglow {

double RepairClock::left() const { return std::max(0.0, limit_ - seconds()); }

void RepairClock::stage(const std::string& figures) const {
    const double s = seconds();
    if (s >= kQuiet) std::fprintf(stderr, "tetglow: repair: %s (%.1f s)\n", figures.c_str(), s);
    if (expired()) stop(figures);
}

void RepairClock::stop(const std::string& figures) const {
    char text[96];
    std::snprintf(text, sizeof text, "the repair reached its time limit of %g s (--repair-time-limit) at ", limit_);
    char took[32];
    std::snprintf(took, sizeof took, " in %.1f s", seconds());
    throw RepairTimeout(text + figures + took);
}

std::string grouped(size_t n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

}  // namespace tetglow
