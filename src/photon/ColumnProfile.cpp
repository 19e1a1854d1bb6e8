#include "photon/ColumnProfile.h"

#include <algorithm>
#include <cmath>

namespace tetglow {

namespace {

// sinh(x) / x; below 0.3 its series to x^6 (within 2e-10), without a transcendental call: the
// beam estimate asks it for every photon along every eye ray.
double sinhc(double x) {
    if (x >= 0.3) return std::sinh(x) / x;
    const double x2 = x * x;
    return 1 + x2 / 6 * (1 + x2 / 20 * (1 + x2 / 42));
}

}  // namespace

ColumnProfile::ColumnProfile(const Volume& volume, const Ray& ray, WalkStart start, double tMax)
    : volume_(volume), ray_(ray) {
    const TetWalk walk = volume.walk(ray, start, [&](const WalkSegment& s) {
        const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
        if (tOut > tIn) {
            const double piece = volume.densityIntegral(s.tet, ray, tIn, tOut);
            const RGB depth = volume.at(s.tet).sigmaT * piece;
            pieces_.push_back({{s.tet, tIn, tOut}, total_, depth_, depth / (tOut - tIn)});
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
    return p->columnIn + volume_.densityIntegral(p->tet, ray_, p->tIn, std::min(t, p->tOut));
}

RGB ColumnProfile::transmittanceIn(const Piece& p, double t) const {
    // In a homogeneous volume the piece's rate is its extinction: no region lookup per call (the
    // beam estimate asks this for every photon along every eye ray).
    if (volume_.homogeneous()) return exp(-(p.depthIn + p.rate * (std::min(t, p.tOut) - p.tIn)));
    return exp(
        -(p.depthIn + volume_.at(p.tet).sigmaT * volume_.densityIntegral(p.tet, ray_, p.tIn, std::min(t, p.tOut))));
}

RGB ColumnProfile::transmittance(double t) const {
    const Piece* p = pieceAt(t);
    return p ? transmittanceIn(*p, t) : RGB(1);
}

RGB ColumnProfile::transmitted(double a, double b) const {
    const double mid = 0.5 * (a + b);
    const Piece* p = pieceAt(mid);
    if (!p) return RGB(0);
    const RGB tr = transmittanceIn(*p, mid);
    RGB out;
    for (int c = 0; c < 3; ++c) out[c] = (b - a) * tr[c] * sinhc(0.5 * p->rate[c] * (b - a));
    return out;
}

std::optional<ColumnProfile::Event> ColumnProfile::atDepth(int c, double depth) const {
    // The last piece starting at or before that depth: depths only grow along the ray.
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), depth,
                                     [c](double d, const Piece& p) { return d < p.depthIn[c]; });
    if (it == pieces_.begin()) return std::nullopt;
    const Piece& p = *(it - 1);
    const double sigma = volume_.at(p.tet).sigmaT[c];
    const double column = (depth - p.depthIn[c]) / sigma;  // still to go in this piece
    const double next = (it == pieces_.end() ? total_ : it->columnIn) - p.columnIn;
    if (!(sigma > 0) || column > next) return std::nullopt;
    return Event{p.tIn + volume_.columnDistance(p.tet, ray_, p.tIn, p.tOut, column), p.tet};
}

std::optional<ColumnProfile::Event> ColumnProfile::at(double t) const {
    const Piece* p = pieceAt(t);
    if (!p || t > end()) return std::nullopt;
    return Event{t, p->tet};
}

}  // namespace tetglow
