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
    // of exact for a point off the surface (see WindingNumber.ExactVersusTree). A cluster made
    // of whole closed, consistently wound shells adds exactly 0 outside its bounding sphere, so
    // many disjoint shells cost a point only those whose sphere holds it.
    double approximate(const glm::dvec3& p) const;
    // Every triangle's solid angle summed (Van Oosterom-Strackee), O(triangles).
    double exact(const glm::dvec3& p) const;
    // approximate, or where that is within `band` of 1/2 (twice the error measured in
    // WindingNumber.ExactVersusTree) a value on the exact sum's side of 1/2, to double precision:
    // the tree opened best first, the cluster with the largest error bound each time, until the
    // bounds' sum is below the value's distance from 1/2. Near an open part, where much of the
    // space lies near 1/2, that opens a few clusters where the exact sum took every triangle.
    double classify(const glm::dvec3& p, double band = 0.05) const;
    // Whether the exact winding number at p is above `level` (by the same opening of the tree).
    bool above(const glm::dvec3& p, double level) const { return certified(p, level) > level; }

    static constexpr double kFarRatio = 2.5;

private:
    struct Node {
        glm::dvec3 centre{0}, area{0};          // area-weighted centroid; sum of area vectors (half the cross products)
        double radius = 0;                      // the farthest corner from centre
        double areaSum = 0;                     // sum of the triangles' areas
        uint32_t begin = 0, end = 0, left = 0;  // triangles order_[begin, end); children left, left + 1 (0: a leaf)
        bool sealed = false;                    // whole closed shells only: 0 outside the radius
    };
    double solidAngle(uint32_t t, const glm::dvec3& p) const {
        return tetglow::solidAngle(soup_.corner(t, 0), soup_.corner(t, 1), soup_.corner(t, 2), p);
    }
    void findShells();
    void build(uint32_t index, uint32_t begin, uint32_t end);
    void sealClusters();
    // A value on the exact winding number's side of `level`.
    double certified(const glm::dvec3& p, double level) const;

    const TriangleMesh& soup_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
    std::vector<uint32_t> shell_;          // by triangle: its small closed shell, or kNoShell
    std::vector<glm::dvec3> shellCentre_;  // by shell: its triangles' mean centroid
};

}  // namespace tetglow
