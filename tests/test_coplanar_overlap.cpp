// Triangles that overlap in one plane: closed letters standing on an open ground quad, boxes
// pressed face to face. CGAL 5.5's autorefinement gives up on them, and the triangles it could
// not split were left out of the constraints.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "tet/CoplanarOverlap.h"
#include "tet/IntersectionResolution.h"
#include "tet/MeshValidation.h"
#include "tet/SelfIntersection.h"
#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

// An I and an L of boxes (the L's two boxes pressed together over part of a face), their bottom
// faces in the plane of a ground quad much larger than they are.
TriangleMesh lettersOnGround(double groundHeight) {
    TriangleMesh m = merge(box({0, 0, 0}, {0.2, 0.2, 1}), box({0.5, 0, 0}, {0.7, 0.2, 1}));
    m = merge(m, box({0.7, 0, 0}, {1.1, 0.2, 0.2}));
    return merge(m, quad({-1, -1, groundHeight}, {5, 0, 0}, {0, 3, 0}));
}
constexpr double kLetters = 0.04 + 0.04 + 0.016;

// The letters keep their volume and the quad, a sheet, encloses nothing: inside is winding number
// above 1/2, which the letters are (about 0.7 with the quad) and the space over the quad is not.
// Their bottom faces on the quad were left unsplit, and the medium was a sliver of 0.0028.
TEST(CoplanarOverlap, LettersOnAGroundQuadKeepTheirVolume) {
    for (const double height : {0.0, -0.01}) {
        ValidationReport report;
        TetOptions options = test::noCache();
        const TetMesh mesh = tetrahedralize(lettersOnGround(height), options, nullptr, &report);
        ASSERT_TRUE(report.repair.applied) << height;
        EXPECT_EQ(report.repair.unsplitTriangles, 0u) << report.repair.summary();
        EXPECT_NEAR(mesh.volume(), kLetters, 1e-6) << height << ": " << report.repair.summary();
        EXPECT_NEAR(mesh.surfaceVolume(), kLetters, 1e-6) << height;
    }
}

// The resolution leaves no crossing and none unsplit, and covers the ground once, with the
// letters' bottoms as pieces of it.
TEST(CoplanarOverlap, SplitsTheUnionAlongEveryEdge) {
    TriangleMesh input = lettersOnGround(0);
    weldVertices(input);
    const auto crossings = findSelfIntersections(input);
    ASSERT_FALSE(crossings.empty());
    TriangleMesh once = input;
    ASSERT_TRUE(splitCoplanarOverlaps(once, crossings));
    const ResolvedSurface resolved = resolveIntersections(input, crossings);
    EXPECT_EQ(resolved.unsplit, 0u) << resolved.unsplitReason;
    const TriangleMesh& m = resolved.surface;
    EXPECT_TRUE(findSelfIntersections(m).empty());
    double groundArea = 0;
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        if (m.corner(t, 0).z == 0 && m.corner(t, 1).z == 0 && m.corner(t, 2).z == 0)
            groundArea +=
                0.5 * glm::length(glm::cross(m.corner(t, 1) - m.corner(t, 0), m.corner(t, 2) - m.corner(t, 0)));
    EXPECT_NEAR(groundArea, 15, 1e-9);
}

}  // namespace
}  // namespace tetglow
