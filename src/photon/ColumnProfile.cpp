#include "photon/ColumnProfile.h"

#include <algorithm>

namespace tetglow {

ColumnProfile::ColumnProfile(const Medium& medium, const Ray& ray, WalkStart start, double tMax) : medium_(medium), ray_(ray) {
    TetWalk walk = medium.beginWalk(ray, start);
    for (WalkSegment s; walk.next(s);) {
        const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
        if (tOut > tIn) {
            pieces_.push_back({tIn, tOut, s.tet, total_});
            total_ += medium.densityIntegral(s.tet, ray, tIn, tOut);
        }
        if (s.tOut >= tMax) break;
    }
}

double ColumnProfile::column(double t) const {
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.tIn; });
    if (it == pieces_.begin()) return 0;
    const Piece& p = *(it - 1);
    if (t >= p.tOut) return p.columnIn + medium_.densityIntegral(p.tet, ray_, p.tIn, p.tOut);
    return p.columnIn + medium_.densityIntegral(p.tet, ray_, p.tIn, t);
}

}  // namespace tetglow
