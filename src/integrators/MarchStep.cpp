#include "integrators/MarchStep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tetglow {

double resolutionOf(const Bounds3& box, const glm::dvec3& origin) {
    double largest = 0;
    for (const glm::dvec3& p : {box.lo, box.hi, origin})
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return 2 * largest * 0x1p-44;
}

void checkMarchStep(const std::string& what, double step, double diagonal, double resolution) {
    const double smallest = std::max(diagonal / kMaxStepsPerDiagonal, resolution);
    if (step >= smallest) return;
    char text[256];
    std::snprintf(
        text, sizeof text,
        " %.6g is too small for this scene: at least %.6g (at most %.0f steps across a bounding box of diagonal %.6g, "
        "and no less than the coordinates resolve)",
        step, smallest, kMaxStepsPerDiagonal, diagonal);
    throw InputError(what + text);
}

}  // namespace tetglow
