#include "tet/Predicates.h"

#include <mutex>

#include <tetgen.h>

// Exported by libtet but not declared in tetgen.h.
REAL orient2d(REAL* pa, REAL* pb, REAL* pc);

namespace tetglow {
namespace {

// libtet's exactinit also sets a static filter sized to one mesh's bounding box; it is disabled
// here (nofilter = 1) so the predicates stay exact for any coordinates.
void init() {
    static std::once_flag once;
    std::call_once(once, [] { exactinit(0, 0, 1, 1, 1, 1); });
}

}  // namespace

double orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    init();
    double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z}, pd[3] = {d.x, d.y, d.z};
    return ::orient3d(pa, pb, pc, pd);
}

double orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    init();
    double pa[2] = {a.x, a.y}, pb[2] = {b.x, b.y}, pc[2] = {c.x, c.y};
    return ::orient2d(pa, pb, pc);
}

}  // namespace tetglow
