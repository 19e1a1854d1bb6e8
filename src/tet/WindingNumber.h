// The generalized winding number of a triangle soup (Jacobson, Kavan and Sorkine-Hornung 2013):
// the signed solid angle its triangles subtend at a point, over 4 pi. 1 inside a closed outward
// surface, 0 outside, and in between where the surface has holes, so it decides inside and
// outside for meshes that do not separate them.
#pragma once
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// The signed solid angle of triangle abc seen from p (Van Oosterom-Strackee): positive where p is
// behind it (its normal, by the right-hand rule, points away from p).
double solidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p);

class WindingNumber {
public:
    explicit WindingNumber(const TriangleMesh& soup);

    // Barill et al. 2018's tree: a cluster of triangles farther than kFarRatio times its radius
    // counts as its area-weighted dipole, nearer ones triangle by triangle. Within about 2e-2
    // of exact for a point off the surface (see WindingNumber.ExactVersusTree).
    double approximate(const glm::dvec3& p) const;
    // Every triangle's solid angle summed (Van Oosterom-Strackee), O(triangles).
    double exact(const glm::dvec3& p) const;
    // approximate, or exact where it is within `band` of 1/2: the side of 1/2 it is on is then
    // the exact one's, to double precision, wherever the tree's error is below the band (twice
    // the error measured in WindingNumber.ExactVersusTree; each exact sum costs as much as
    // thousands of tree evaluations on a large mesh).
    double classify(const glm::dvec3& p, double band = 0.05) const;

    static constexpr double kFarRatio = 2.5;

private:
    struct Node {
        glm::dvec3 centre{0}, area{0};          // area-weighted centroid; sum of area vectors (half the cross products)
        double radius = 0;                      // the farthest corner from centre
        uint32_t begin = 0, end = 0, left = 0;  // triangles order_[begin, end); children left, left + 1 (0: a leaf)
    };
    double solidAngle(uint32_t t, const glm::dvec3& p) const {
        return tetglow::solidAngle(soup_.corner(t, 0), soup_.corner(t, 1), soup_.corner(t, 2), p);
    }
    void build(uint32_t index, uint32_t begin, uint32_t end);

    const TriangleMesh& soup_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

}  // namespace tetglow
