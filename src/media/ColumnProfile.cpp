#include "media/ColumnProfile.h"

#include <algorithm>
#include <cmath>

namespace tetglow {

namespace {

// The transmittance integrated over a stretch of length `length` that starts at transmittance
// trIn and gains optical depth `depth` linearly along it.
RGB transmittedOver(double length, const RGB& trIn, const RGB& depth) {
    RGB out;
    for (int c = 0; c < 3; ++c) out[c] = length * trIn[c] * (depth[c] > 1e-12 ? -std::expm1(-depth[c]) / depth[c] : 1);
    return out;
}

}  // namespace

ColumnProfile::ColumnProfile(const RegionMedia& medium, const Ray& ray, WalkStart start, double tMax)
    : medium_(medium), ray_(ray) {
    const TetWalk walk = medium.walk(ray, start, [&](const WalkSegment& s) {
        const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
        if (tOut > tIn) {
            pieces_.push_back({tIn, tOut, s.tet, total_, depth_, transmitted_});
            const double piece = medium.densityIntegral(s.tet, ray, tIn, tOut);
            const RGB depth = medium.at(s.tet).sigmaT * piece;
            transmitted_ += transmittedOver(tOut - tIn, exp(-depth_), depth);
            total_ += piece;
            depth_ += depth;
        }
        return s.tOut < tMax;
    });
    exit_ = WalkExit::of(walk, tMax);
}

const ColumnProfile::Piece* ColumnProfile::pieceAt(double t) const {
    const auto it =
        std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.tIn; });
    return it == pieces_.begin() ? nullptr : &*(it - 1);
}

double ColumnProfile::column(double t) const {
    const Piece* p = pieceAt(t);
    if (!p) return 0;
    return p->columnIn + medium_.densityIntegral(p->tet, ray_, p->tIn, std::min(t, p->tOut));
}

RGB ColumnProfile::transmittance(double t) const {
    const Piece* p = pieceAt(t);
    if (!p) return RGB(1);
    return exp(-(p->depthIn +
                 medium_.at(p->tet).sigmaT * medium_.densityIntegral(p->tet, ray_, p->tIn, std::min(t, p->tOut))));
}

RGB ColumnProfile::transmitted(double t) const {
    const Piece* p = pieceAt(t);
    if (!p) return RGB(0);
    const double tOut = std::min(t, p->tOut);
    const RGB depth = medium_.at(p->tet).sigmaT * medium_.densityIntegral(p->tet, ray_, p->tIn, tOut);
    return p->transmittedIn + transmittedOver(tOut - p->tIn, exp(-p->depthIn), depth);
}

RGB ColumnProfile::transmitted(double a, double b) const {
    const Piece* p = pieceAt(a);
    if (!p || b > p->tOut) return transmitted(b) - transmitted(a);
    const RGB& sigmaT = medium_.at(p->tet).sigmaT;
    const RGB trA = exp(-(p->depthIn + sigmaT * medium_.densityIntegral(p->tet, ray_, p->tIn, a)));
    return transmittedOver(b - a, trA, sigmaT * medium_.densityIntegral(p->tet, ray_, a, b));
}

std::optional<ColumnProfile::Event> ColumnProfile::atDepth(int c, double depth) const {
    // The last piece starting at or before that depth: depths only grow along the ray.
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), depth,
                                     [c](double d, const Piece& p) { return d < p.depthIn[c]; });
    if (it == pieces_.begin()) return std::nullopt;
    const Piece& p = *(it - 1);
    const double sigma = medium_.at(p.tet).sigmaT[c];
    const double column = (depth - p.depthIn[c]) / sigma;  // still to go in this piece
    const double next = (it == pieces_.end() ? total_ : it->columnIn) - p.columnIn;
    if (!(sigma > 0) || column > next) return std::nullopt;
    return Event{p.tIn + medium_.columnDistance(p.tet, ray_, p.tIn, p.tOut, column), p.tet};
}

}  // namespace tetglow
