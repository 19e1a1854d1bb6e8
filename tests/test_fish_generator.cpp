// The procedural demo fish: valid TetGen input at every resolution, and the committed
// scenes/meshes/fish.obj is exactly what the generator makes by default.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "scene/FishGenerator.h"
#include "scene/MeshFile.h"
#include "scene/SceneLoader.h"
#include "tet/Nesting.h"
#include "tet/SelfIntersection.h"

namespace tetglow {
namespace {

FishParams resolution(int rings, int segments) {
    FishParams p;
    p.rings = rings;
    p.segments = segments;
    return p;
}

// Balanced resolutions from coarse to the ~200k triangles of the render-cost study.
const std::vector<FishParams> kResolutions = {resolution(16, 16), resolution(32, 24),   resolution(64, 48),
                                              FishParams{},       resolution(200, 160), resolution(440, 420)};

// Every undirected edge is shared by exactly two triangles that run it in opposite directions.
void expectClosedAndConsistent(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice in one direction";
        const auto twin = directed.find({edge.second, edge.first});
        ASSERT_TRUE(twin != directed.end()) << "edge " << edge.first << "-" << edge.second << " is a boundary";
    }
}

// Connected shells (by shared vertices), as a shell index per vertex.
std::vector<uint32_t> shells(const TriangleMesh& m, uint32_t& count) {
    std::vector<uint32_t> parent(m.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& t : m.triangles) parent[root(t[1])] = parent[root(t[2])] = root(t[0]);
    std::map<uint32_t, uint32_t> index;
    std::vector<uint32_t> shell(m.positions.size());
    for (uint32_t v = 0; v < shell.size(); ++v) shell[v] = index.emplace(root(v), index.size()).first->second;
    count = static_cast<uint32_t>(index.size());
    return shell;
}

void expectValidMedium(const TriangleMesh& m) {
    expectClosedAndConsistent(m);
    EXPECT_GT(signedVolume(m), 0) << "inward winding";
    EXPECT_GT(test::minAngleDegrees(m), 1.0) << "sliver triangles";

    std::set<std::tuple<double, double, double>> distinct;
    for (const auto& p : m.positions) {
        EXPECT_TRUE(roundToFloat(p.x) == p.x && roundToFloat(p.y) == p.y && roundToFloat(p.z) == p.z)
            << "position not rounded to float";
        distinct.insert({p.x, p.y, p.z});
    }
    EXPECT_EQ(distinct.size(), m.positions.size()) << "duplicate vertices";
    const auto hit = findSelfIntersection(m);
    EXPECT_FALSE(hit) << "triangles " << hit->first << " and " << hit->second << " intersect";
}

// The showcase's organs: valid media of their own, nested in the body (every vertex inside it,
// exactly, and no triangle of theirs crossing one of the body's), at the default resolution and a
// coarse one; a body too coarse to hold them is an error, not organs poking out.
TEST(FishGenerator, OrgansAreValidAndNestedInTheBody) {
    for (const FishParams& p : {FishParams{}, resolution(32, 24)}) {
        const TriangleMesh body = makeFish(p);
        const std::pair<TriangleMesh, size_t> parts[] = {
            {makeFishPhotophores(p), 14}, {makeFishEyes(p), 2}, {makeFishLureCore(p), 1}};
        for (const auto& [organ, expectedShells] : parts) {
            expectValidMedium(organ);
            uint32_t count = 0;
            shells(organ, count);
            EXPECT_EQ(count, expectedShells);
            for (const auto& v : organ.positions) ASSERT_EQ(classifyPoint(body, v), PointSide::Inside);
            TriangleMesh both = body;
            const auto base = static_cast<uint32_t>(both.positions.size());
            both.positions.insert(both.positions.end(), organ.positions.begin(), organ.positions.end());
            for (const auto& t : organ.triangles) both.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
            EXPECT_FALSE(findSelfIntersection(both)) << "an organ crosses the body";
        }
    }
    try {
        makeFishPhotophores(resolution(8, 8));
        FAIL() << "photophores placed in an 8 x 8 body";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "fish: photophores do not fit inside the fish at 8 rings and 8 segments: use more of either");
    }
}

TEST(FishGenerator, DefaultIsAValidMedium) {
    const TriangleMesh m = makeFish();
    EXPECT_GE(m.triangles.size(), 5000u);
    EXPECT_LE(m.triangles.size(), 20000u);
    expectValidMedium(m);

    // About 2 long, nose at +x, about 0.8 tall, centred near the origin.
    const Bounds3 b = bounds(m);
    EXPECT_NEAR(b.hi.x - b.lo.x, 2.0, 0.1);
    EXPECT_NEAR(b.hi.y - b.lo.y, 0.8, 0.1);
    EXPECT_LT(std::abs(b.lo.x + b.hi.x), 0.2);
}

TEST(FishGenerator, EveryResolutionIsAValidMedium) {
    for (const auto& p : kResolutions) {
        SCOPED_TRACE(std::to_string(p.rings) + " x " + std::to_string(p.segments));
        expectValidMedium(makeFish(p));
    }
}

TEST(FishGenerator, ShapeKnobsAtTheirLimitsStayValid) {
    FishParams thin;
    thin.finThickness = 0.02;
    thin.tailFork = 0.3;
    thin.lureRadius = 0.1;
    expectValidMedium(makeFish(thin));
    FishParams plain;
    plain.finThickness = 0.08;
    plain.tailFork = 0;
    plain.lureRadius = 0;
    expectValidMedium(makeFish(plain));
    FishParams smallLure;
    smallLure.lureRadius = 0.02;
    expectValidMedium(makeFish(smallLure));
}

// Why it cannot self-intersect at any resolution: mirror-symmetric about z = 0, with the half
// at z >= 0 a height field over the x-y plane, so no triangle of it folds over in projection.
TEST(FishGenerator, LeftHalfProjectsWithoutFolds) {
    for (const auto& p : kResolutions) {
        const TriangleMesh m = makeFish(p);
        size_t folds = 0;
        for (uint32_t t = 0; t < m.triangles.size(); ++t) {
            const glm::dvec3 a = m.corner(t, 0), b = m.corner(t, 1), c = m.corner(t, 2);
            if (a.z < 0 || b.z < 0 || c.z < 0) continue;
            folds += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) <= 0;
        }
        EXPECT_EQ(folds, 0u) << p.rings << " x " << p.segments;
    }
}

FishParams withoutLure(FishParams p = {}) {
    p.lureRadius = 0;
    return p;
}

// The lure is a shell of its own: a bulb ahead of the nose on a stalk that rises from the head,
// behind the nose, wholly outside the body (the whole mesh's self-intersection test above holds
// for the two shells together).
TEST(FishGenerator, LureOnAStalkFromTheHeadIsAShellOutsideTheBody) {
    const TriangleMesh m = makeFish();
    uint32_t count = 0;
    const std::vector<uint32_t> shell = shells(m, count);
    ASSERT_EQ(count, 2u);
    const TriangleMesh body = makeFish(withoutLure());
    Bounds3 lure;
    for (uint32_t v = 0; v < m.positions.size(); ++v)
        if (shell[v] != shell[0]) {
            lure.extend(m.positions[v]);
            ASSERT_EQ(classifyPoint(body, m.positions[v]), PointSide::Outside)
                << "lure vertex " << v << " inside the body";
        }
    const Bounds3 b = bounds(body);
    EXPECT_GT(lure.hi.x, b.hi.x);           // the bulb hangs ahead of the nose,
    EXPECT_LT(lure.lo.x, b.hi.x - 0.15);    // the stalk rises from the head behind it,
    EXPECT_LT(lure.lo.y, b.hi.y);           // from below the top of the back,
    EXPECT_GT(lure.hi.y - lure.lo.y, 0.1);  // and arches up to the bulb.

    shells(makeFish(withoutLure()), count);
    EXPECT_EQ(count, 1u);
}

// Documented: about 1.1 * rings * segments triangles for the body, growing with rings * segments,
// and a lure of at most a fifth as many.
TEST(FishGenerator, TriangleCountScalesWithRingsTimesSegments) {
    size_t previous = 0;
    for (const auto& p : kResolutions) {
        const size_t n = makeFish(p).triangles.size(), bodyOnly = makeFish(withoutLure(p)).triangles.size();
        EXPECT_LT(double(n - bodyOnly), 0.2 * double(bodyOnly)) << p.rings << " x " << p.segments;
        const double perCell = double(bodyOnly) / (p.rings * p.segments);
        EXPECT_GT(perCell, 0.95) << p.rings << " x " << p.segments;
        EXPECT_LT(perCell, 1.25) << p.rings << " x " << p.segments;
        EXPECT_GT(n, previous);
        previous = n;
    }
    EXPECT_LT(makeFish(resolution(16, 16)).triangles.size(), 500u);       // a few hundred
    EXPECT_GT(makeFish(resolution(440, 420)).triangles.size(), 180000u);  // ~200k
}

TEST(FishGenerator, RejectsParametersOutOfRange) {
    EXPECT_THROW(makeFish(resolution(7, 16)), InputError);
    EXPECT_THROW(makeFish(resolution(16, 4)), InputError);
    EXPECT_THROW(makeFish(resolution(4096, 2048)), InputError);
    EXPECT_THROW(makeFish(resolution(400, 20)), InputError);  // needle triangles
    FishParams p;
    p.finThickness = 0.001;
    EXPECT_THROW(makeFish(p), InputError);
    p = {};
    p.lureRadius = std::nan("");
    EXPECT_THROW(makeFish(p), InputError);
}

// The committed meshes of the demo (scenes/meshes) are exactly what the generator makes by default.
TEST(FishGenerator, CommittedObjsAreTheDefaultFishAndItsOrgans) {
    const std::pair<std::string, TriangleMesh (*)(const FishParams&)> parts[] = {
        {"fish", makeFish},
        {"fish-photophores", makeFishPhotophores},
        {"fish-eyes", makeFishEyes},
        {"fish-lure-core", makeFishLureCore}};
    for (const auto& [name, make] : parts) {
        SCOPED_TRACE(name);
        const TriangleMesh expected = make({});
        const std::string file = "scenes/meshes/" + name + ".obj";
        const TriangleMesh committed = readMesh(TETGLOW_SOURCE_DIR "/" + file);
        ASSERT_EQ(committed.positions.size(), expected.positions.size())
            << "regenerate: tetglow generate " << name << " -o " << file;
        ASSERT_EQ(committed.triangles.size(), expected.triangles.size());
        // Nine digits bring float positions back exactly once snapped to float, as validation does.
        for (size_t v = 0; v < expected.positions.size(); ++v) {
            ASSERT_LT(glm::distance(committed.positions[v], expected.positions[v]), 1e-6) << "vertex " << v;
            const glm::dvec3& c = committed.positions[v];
            ASSERT_EQ(glm::dvec3(roundToFloat(c.x), roundToFloat(c.y), roundToFloat(c.z)), expected.positions[v])
                << "vertex " << v;
        }
        EXPECT_EQ(committed.triangles, expected.triangles);
    }
}

// The demo scenes name each medium by what it is (the preview's titles), each on its own mesh.
TEST(FishGenerator, TheDemoScenesNameTheirMedia) {
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"/media/0 (meshes/fish.obj)", "body"},
        {"/media/1 (meshes/fish-photophores.obj)", "photophores"},
        {"/media/2 (meshes/fish-lure-core.obj)", "lure"},
        {"/media/3 (meshes/fish-eyes.obj)", "eyes"},
        {"/media/4", "water"}};
    for (const std::string scene : {"fish", "fish-closeup"}) {
        std::vector<std::pair<std::string, std::string>> named;
        for (const MediumDesc& m : loadScene(TETGLOW_SOURCE_DIR "/scenes/" + scene + ".json").media)
            named.emplace_back(m.name, m.label);
        EXPECT_EQ(named, expected) << scene;
    }
}

}  // namespace
}  // namespace tetglow
