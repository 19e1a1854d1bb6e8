// The density integrated along a ray inside one medium (its "column"), piece by piece as the
// tet walk crossed it, so that the transmittance to any point on the ray is exact and costs
// one binary search: exp(-sigma_t * column(t)).
#pragma once
#include <vector>

#include "photon/Medium.h"

namespace tetglow {

class ColumnProfile {
public:
    struct Piece {
        double tIn, tOut;
        uint32_t tet;
        double columnIn;  // from the start to tIn
    };
    // From `start` to tMax or to where the ray leaves the medium (unit direction).
    ColumnProfile(const Medium& medium, const Ray& ray, WalkStart start, double tMax);

    const std::vector<Piece>& pieces() const { return pieces_; }
    double begin() const { return pieces_.empty() ? 0 : pieces_.front().tIn; }
    double end() const { return pieces_.empty() ? 0 : pieces_.back().tOut; }
    double total() const { return total_; }
    // Column from the start to t, clamped to [begin, end].
    double column(double t) const;
    RGB transmittance(double t) const { return exp(-medium_.sigmaT() * column(t)); }

private:
    const Medium& medium_;
    Ray ray_;
    std::vector<Piece> pieces_;
    double total_ = 0;
};

}  // namespace tetglow
