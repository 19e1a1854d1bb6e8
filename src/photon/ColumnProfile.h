// The density integrated along a ray through a medium's regions (its "column"), piece by piece
// as the tet walk crossed it, with the optical depth at each piece's start, so that the
// transmittance to any point on the ray is exact and costs one binary search; so does the
// transmittance integrated over a stretch of the ray, which a kernel wider than the mean free
// path needs.
#pragma once
#include <optional>
#include <vector>

#include "media/Volume.h"

namespace tetglow {

class ColumnProfile {
public:
    // The part of a walk's segment within the stretch, with what the profile adds to it.
    struct Piece : WalkSegment {
        double columnIn;  // from the start to tIn
        RGB depthIn;      // optical depth from the start to tIn
        RGB rate;         // optical depth per unit length, on average over the piece
    };
    // From `start` to tMax or to where the ray leaves the medium or stops at an interface (unit
    // direction).
    ColumnProfile(const Volume& volume, const Ray& ray, WalkStart start, double tMax);

    const std::vector<Piece>& pieces() const { return pieces_; }
    double begin() const { return pieces_.empty() ? 0 : pieces_.front().tIn; }
    double end() const { return pieces_.empty() ? 0 : pieces_.back().tOut; }
    double total() const { return total_; }
    RGB depth() const { return depth_; }            // optical depth of the whole stretch
    const WalkExit& exit() const { return exit_; }  // where the walk left or stopped, if before tMax
    // Column from the start to t, clamped to [begin, end].
    double column(double t) const;
    RGB transmittance(double t) const;
    // The transmittance integrated over [a, b] (begin <= a <= b <= end): the midpoint's
    // transmittance times b - a times sinh(x) / x, x half the optical depth of [a, b] at the
    // midpoint piece's rate. Exact where [a, b] lies in one piece of constant density; one
    // lookup, as transmittance(t) costs.
    RGB transmitted(double a, double b) const;
    // Where channel c's optical depth from the start reaches `depth`, or null where the stretch
    // ends first: a free flight sampled from the profile, without walking the tets again.
    struct Event {
        double t;
        uint32_t tet;
    };
    std::optional<Event> atDepth(int c, double depth) const;
    // The point at t (begin <= t <= end) and its tet.
    std::optional<Event> at(double t) const;

private:
    // The piece holding t (the last one starting at or before it), or null before the first.
    const Piece* pieceAt(double t) const;
    // The transmittance to t, which lies in `p` or past its end (then to its end).
    RGB transmittanceIn(const Piece& p, double t) const;

    const Volume& volume_;
    Ray ray_;
    std::vector<Piece> pieces_;
    double total_ = 0;
    RGB depth_{0};
    WalkExit exit_;
};

}  // namespace tetglow
