// The bound on a repair's time (--repair-time-limit) and TetGen's merging of close vertices:
// a repair past its bound stops at the stage it reached and the mesh is approximated, with a
// warning naming the stage and its figures; vertices nearer than TetGen's tolerance stay apart.
#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "tet/Shapes.h"
#include "tet/TetGenProcess.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

// Two unit boxes overlapping in a cube of side 1/2: the union is 2 - 1/8.
TriangleMesh crossingBoxes() { return merge(box(), box(glm::dvec3(0.5), glm::dvec3(1.5))); }

// A bound of 0 s: the repair stops at its first stage, and the mesh is the winding number's grid,
// named, with the stage and its figures, instead of the exact union.
TEST(RepairTimeLimit, ZeroTakesTheGridAndSaysWhereItStopped) {
    TetOptions options = test::noCache();
    options.repairTimeLimit = 0;
    TetStats stats;
    std::vector<ValidationReport> reports;
    const TetMesh mesh = tetrahedralize({crossingBoxes()}, {"boxes.obj"}, options, &stats, &reports);
    EXPECT_FALSE(reports[0].repair.approximateReason.empty());
    const std::string& warning = stats.approximateWarning;
    EXPECT_EQ(warning.rfind("boxes.obj: the boundary is approximate", 0), 0u) << warning;
    EXPECT_NE(warning.find("the repair reached its time limit of 0 s (--repair-time-limit) at cleaning: 24 "
                           "triangles welded and oriented in "),
              std::string::npos)
        << warning;
    EXPECT_EQ(warning.find('\n'), std::string::npos) << warning;
    EXPECT_NEAR(mesh.volume(), 1.875, 0.03 * 1.875);
}

// With the default bound the same mesh takes the exact path: the union, exactly.
TEST(RepairTimeLimit, DefaultBoundRepairsExactly) {
    TetStats stats;
    ValidationReport report;
    const TetMesh mesh = tetrahedralize(crossingBoxes(), test::noCache(), &stats, &report);
    EXPECT_TRUE(report.repair.applied);
    EXPECT_TRUE(stats.approximateWarning.empty()) << stats.approximateWarning;
    EXPECT_NEAR(mesh.volume(), 1.875, 1e-9);
}

// Two boxes 1e-9 apart at a corner (1.7e-9, under TetGen's 1e-8 of the diagonal, 3.5e-8): valid,
// and TetGen merged the corners, so its output lost a vertex ("TetGen moved input vertex"), and
// the mesh became the winding number's grid. Both boxes stay, exactly.
TEST(RepairTimeLimit, VerticesNearerThanTetGensToleranceStayApart) {
    const double gap = 1e-9;
    const TriangleMesh both = merge(box(), box(glm::dvec3(-1), glm::dvec3(-gap)));
    ASSERT_TRUE(hasCloseVertices(both.positions));
    ASSERT_FALSE(hasCloseVertices(box().positions));
    TetStats stats;
    ValidationReport report;
    const TetMesh mesh = tetrahedralize(both, test::noCache(), &stats, &report);
    EXPECT_TRUE(stats.approximateWarning.empty()) << stats.approximateWarning;
    EXPECT_FALSE(report.repair.applied);
    EXPECT_EQ(mesh.surfaceVertexCount, 16u);
    EXPECT_NEAR(mesh.volume(), 1 + (1 - gap) * (1 - gap) * (1 - gap), 1e-12);
}

}  // namespace
}  // namespace tetglow
