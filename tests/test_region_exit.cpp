// A region's exit in one surface-BVH query: the same triangle, tet and t as the walk's exit, for
// random rays and for rays constructed through vertices and edges of the boundary; and the
// transmittance and shadow rays built on it equal the closed form and the walk.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "ExitQueryAccess.h"
#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/PathStep.h"
#include "media/ShadowRay.h"
#include "media/Volume.h"
#include "scene/MeshFile.h"
#include "scene/Scene.h"
#include "tet/Predicates.h"
#include "tet/RegionExit.h"
#include "tet/TetTraversal.h"

namespace tetglow {
namespace {

// A ray from a random point of the cube of half-width 0.9 in a random direction, and the tet that
// holds the point; nothing where the point lies outside the medium.
struct InteriorRay {
    Ray ray;
    uint32_t tet;
};
std::optional<InteriorRay> interiorRay(const Volume& volume, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    const glm::dvec3 p(0.9 * u(rng), 0.9 * u(rng), 0.9 * u(rng));
    const int64_t tet = volume.traversal().locate(p);
    if (tet < 0) return std::nullopt;
    return InteriorRay{{p, test::onSphere(rng, 1)}, uint32_t(tet)};
}

struct ExitCounts {
    size_t compared = 0, unsure = 0, walkLost = 0, illPosed = 0;
};

// A tet with an edge exactly parallel to the ray (its ends project to one point) or a face in a
// plane with the ray (its corners project onto a line through the origin): the walk's signs
// there are fixed choices, not those of a perturbed line, and the walk may leave through a face
// the line does not cross, or at a t off the surface.
bool degenerateAlongRay(const TetMesh& mesh, uint32_t tet, const Ray& ray) {
    const RayProjection project(ray);
    const auto& v = mesh.tets[tet];
    glm::dvec2 p[4];
    for (int i = 0; i < 4; ++i) p[i] = project(mesh.vertices[v[i]]).uv;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (glm::cross(mesh.vertices[v[j]] - mesh.vertices[v[i]], ray.d) == glm::dvec3(0)) return true;
    for (const auto& f : kInwardFace)
        if (orient2d(p[f[0]], p[f[1]], {0, 0}) == 0 && orient2d(p[f[1]], p[f[2]], {0, 0}) == 0 &&
            orient2d(p[f[2]], p[f[0]], {0, 0}) == 0)
            return true;
    return false;
}

// Walks `steps` segments of the ray from `tet` (holding its origin), asks regionExit from there
// and compares it with the rest of the walk, to the region's first exit.
void compareExit(const TetTraversal& volume, const Ray& ray, uint32_t tet, int steps, ExitCounts& counts) {
    const TetMesh& mesh = volume.mesh();
    TetWalk walk = TetWalk::start(mesh, ray, tet, 0);
    WalkSegment s{};
    bool illPosed = false;
    for (int k = 0; k < steps; ++k) {
        if (!walk.next(s)) return;
        // A first segment that ends where it starts: an origin on a tet face the perturbed ray
        // does not go into from this tet, where the walk's own start is undefined.
        illPosed |= (k == 0 && !(s.tOut > s.tIn)) || degenerateAlongRay(mesh, s.tet, ray);
    }
    if (walk.exited()) return;
    const RegionExit e = regionExit(volume, ray, mesh.region(s.tet), s.tOut, INFINITY);
    for (WalkSegment rest; walk.next(rest);) illPosed |= degenerateAlongRay(mesh, rest.tet, ray);
    if (illPosed) {
        ++counts.illPosed;
        return;
    }
    if (walk.lost()) {  // the walk's own failure, which expectMostCompared refuses
        ++counts.walkLost;
        return;
    }
    if (e.kind == RegionExit::Kind::Unsure) {
        ++counts.unsure;
        return;
    }
    ASSERT_EQ(int(e.kind), int(RegionExit::Kind::Exit));
    ASSERT_EQ(e.triangle, walk.exitTriangle())
        << "ray " << ray.o.x << " " << ray.o.y << " " << ray.o.z << " d " << ray.d.x << " " << ray.d.y << " " << ray.d.z
        << " t " << e.t << " walk " << walk.exitT() << " from " << s.tOut << " steps " << steps;
    ASSERT_EQ(e.tet, walk.exitTet());
    ASSERT_NEAR(e.t, walk.exitT(), 1e-12 * std::max(1.0, std::abs(e.t)));
    ++counts.compared;
}

ExitCounts compareExits(const TetTraversal& volume, uint64_t seed) {
    const TetMesh& mesh = volume.mesh();
    const Bounds3& box = volume.bounds();
    const double diagonal = box.diagonal();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    ExitCounts counts;
    auto inside = [&](glm::dvec3& p) {
        for (;;) {
            p = box.lo + (box.hi - box.lo) * glm::dvec3(u(rng), u(rng), u(rng));
            if (const int64_t t = volume.locate(p); t >= 0) return uint32_t(t);
        }
    };
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 p;
        const uint32_t tet = inside(p);
        const int steps = 1 + i % 4;
        // Random directions; aimed at a surface vertex; aimed at the midpoint of a surface edge.
        compareExit(volume, {p, test::onSphere(rng, 1)}, tet, steps, counts);
        const auto& tri = mesh.surface[size_t(u(rng) * double(mesh.surface.size())) % mesh.surface.size()];
        compareExit(volume, {p, mesh.vertices[tri[0]] - p}, tet, steps, counts);
        compareExit(volume, {p, 0.5 * (mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) - p}, tet, steps, counts);
    }
    for (int i = 0; i < 1000; ++i) {
        // Axis-parallel through a surface vertex: its projection is exactly the origin, and
        // simulation of simplicity decides.
        const uint32_t v = uint32_t(u(rng) * double(mesh.surfaceVertexCount)) % uint32_t(mesh.surfaceVertexCount);
        const int axis = i % 3;
        for (const double sign : {1.0, -1.0}) {
            glm::dvec3 d(0);
            d[axis] = sign;
            glm::dvec3 p = mesh.vertices[v];
            p[axis] -= sign * (0.01 + 0.2 * u(rng)) * diagonal;
            if (const int64_t t = volume.locate(p); t >= 0) compareExit(volume, {p, d}, uint32_t(t), 1 + i % 3, counts);
        }
        // From a vertex of the tets, and from the centre of a tet face (as a shadow ray from a
        // scattering event there), in the tet the ray goes into: one holding the origin and a
        // point just along the ray.
        const uint32_t w = uint32_t(u(rng) * double(mesh.vertices.size())) % uint32_t(mesh.vertices.size());
        const auto& tv = mesh.tets[uint32_t(u(rng) * double(mesh.tets.size())) % uint32_t(mesh.tets.size())];
        for (const glm::dvec3& p :
             {mesh.vertices[w], (mesh.vertices[tv[0]] + mesh.vertices[tv[1]] + mesh.vertices[tv[2]]) / 3.0}) {
            const glm::dvec3 d = test::onSphere(rng, 1);
            const int64_t t = volume.locate(p + 1e-9 * diagonal * d);
            if (t >= 0 && volume.contains(uint32_t(t), p)) compareExit(volume, {p, d}, uint32_t(t), 1 + i % 3, counts);
        }
    }
    return counts;
}

void expectMostCompared(const ExitCounts& counts, const std::string& name) {
    printf(
        "%s: %zu exits equal to the walk's, %zu left to the walk, %zu where the walk was lost, %zu ill-posed starts\n",
        name.c_str(), counts.compared, counts.unsure, counts.walkLost, counts.illPosed);
    // Unsure (two crossings closer than the walk's rounding): the caller walks; it must stay rare.
    EXPECT_GT(counts.compared, 9000u) << name;
    EXPECT_LT(counts.unsure, counts.compared / 20) << name;
    // The walk decides every step with exact predicates, so a ray with a well-posed start is
    // never lost (TetWalk::lost): a loss is the walk's own bug, not one the exit query can hide.
    EXPECT_EQ(counts.walkLost, 0u) << name;
}

TEST(RegionExit, IsTheWalksExitInTheUnitIcosphere) {
    const TetTraversal volume(tetrahedralize(icosphere(3), test::noCache()));
    expectMostCompared(compareExits(volume, 1), "icosphere");
}

class RegionExitInReferenceMesh : public testing::TestWithParam<test::NamedMesh> {};

TEST_P(RegionExitInReferenceMesh, IsTheWalksExit) {
    const test::NamedMesh& m = GetParam();
    if (m.path.empty()) GTEST_SKIP() << m.name << ".obj not tested: ../shared/meshes not found";
    const TetTraversal volume(tetrahedralize(readMesh(m.path), test::noCache()));
    expectMostCompared(compareExits(volume, 2), m.name);
}

INSTANTIATE_TEST_SUITE_P(Meshes, RegionExitInReferenceMesh, testing::ValuesIn(test::referenceMeshes()), test::meshName);

TEST(RegionExit, IsTheWalksExitAtInterfacesOfNestedSpheres) {
    // Region by region: the exit from the inner sphere's region is the interface, and from the
    // shell it is the interface or the outer surface.
    TetOptions o;
    o.useCache = false;
    const TetTraversal volume(
        tetrahedralize({icosphere(3, 1.0), icosphere(2, 0.5, {0.1, 0.05, 0})}, {"shell", "core"}, o));
    ASSERT_EQ(volume.mesh().regionCount(), 2u);
    expectMostCompared(compareExits(volume, 3), "nested spheres");
}

// A homogeneous absorbing sphere.
std::unique_ptr<Volume> absorbingSphere(double sigma) {
    MediumParams p;
    p.sigmaA = RGB(sigma);
    p.sigmaS = RGB(0);
    return std::make_unique<Volume>(p, tetrahedralize(icosphere(3), test::noCache()));
}

TEST(RegionMediaExit, TransmittanceAlongAChordIsTheClosedForm) {
    const double sigma = 1.7;
    const auto volume = absorbingSphere(sigma);
    const TriangleMesh sphere = icosphere(3);
    std::mt19937_64 rng(4);
    const uint64_t queries = surfaceQueries();
    for (int i = 0; i < 2000; ++i) {
        const auto drawn = interiorRay(*volume, rng);
        if (!drawn) continue;
        const auto [ray, tet] = *drawn;
        const double chord = test::convexChord(sphere, ray);
        // To the boundary, and up to a distance inside (the jump ends there): the closed form
        // (to the float rounding of the tets' vertices) and the walk's (to the last bits).
        for (const double end : {double(INFINITY), 0.5 * chord}) {
            ExitQueryAccess::setExitQueryAfter(*volume, 0);
            const RGB walked = transmittance(*volume, ray, WalkStart::inside(uint32_t(tet)), end);
            ExitQueryAccess::setExitQueryAfter(*volume, 1 + size_t(i % 4));
            const RGB tr = transmittance(*volume, ray, WalkStart::inside(uint32_t(tet)), end);
            ASSERT_NEAR(tr.x, std::exp(-sigma * std::min(chord, end)), 1e-6);
            ASSERT_NEAR(tr.x, walked.x, 1e-12);
        }
    }
    // The exits were found by the surface BVH (a walk makes no query).
    EXPECT_GT(surfaceQueries() - queries, 1000u);
}

// shadowFlight and transmittance with the exit query and with the walk of every tet agree:
// the same exit (triangle, tet, t), the same transmittance.
void expectSameAsTheWalk(Volume& volume, uint64_t seed) {
    std::mt19937_64 rng(seed);
    size_t left = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto drawn = interiorRay(volume, rng);
        if (!drawn) continue;
        const auto [ray, tet] = *drawn;
        const WalkStart start = WalkStart::inside(uint32_t(tet));
        FreeFlight flights[2], shadows[2];
        for (const size_t k : {0, 1}) {
            ExitQueryAccess::setExitQueryAfter(volume, k == 0 ? 0 : 1 + size_t(i % 3));
            Rng r(7, uint64_t(i));
            shadows[k] = shadowFlight(volume, ray, start, INFINITY, r);
            flights[k] = sampleFlight(volume, ray, start, INFINITY, 0, 1.0);
        }
        for (const FreeFlight* f : {flights, shadows}) {
            ASSERT_EQ(f[1].exit.left, f[0].exit.left);
            ASSERT_EQ(f[1].exit.triangle, f[0].exit.triangle);
            ASSERT_EQ(f[1].exit.tet, f[0].exit.tet);
            ASSERT_NEAR(f[1].exit.t, f[0].exit.t, 1e-12);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(f[1].transmittance[c], f[0].transmittance[c], 1e-12);
        }
        left += flights[0].exit.left;
    }
    EXPECT_GT(left, 1000u);
}

TEST(RegionMediaExit, ShadowRaysLeaveWhereTheWalkLeaves) {
    // Thin enough that roulette never starts (optical depth below ln 20).
    const auto volume = absorbingSphere(0.5);
    expectSameAsTheWalk(*volume, 5);
}

// A unit sphere (the shell) holding an off-centre sphere of radius 0.5 (the core), index-matched.
Volume nestedSpheres(const MediumParams& shell, const MediumParams& core) {
    TetOptions o;
    o.useCache = false;
    TetMesh mesh = tetrahedralize({icosphere(3, 1.0), icosphere(2, 0.5, {0.1, 0.05, 0})}, {"shell", "core"}, o);
    return Volume(std::move(mesh), {MediumField{shell, {}}, MediumField{core, {}}});
}

// The same, both scattering and thin enough that flights jump.
Volume scatteringNestedSpheres() {
    MediumParams shell, core;
    shell.sigmaA = RGB(0.1, 0.15, 0.2);
    shell.sigmaS = RGB(0.3);
    core.sigmaA = RGB(0.2, 0.05, 0.1);
    core.sigmaS = RGB(0.4);
    return nestedSpheres(shell, core);
}

// Flights stop at the interface between the two (a dielectric there).
void stopAtInterfaces(Volume& volume) {
    std::vector<bool> stops(volume.mesh().surface.size());
    for (size_t s = 0; s < stops.size(); ++s) stops[s] = volume.mesh().surfaceFaceFront[s] != UINT32_MAX;
    volume.setStops(stops);
}

TEST(RegionMediaExit, NestedRegionsCrossOrStopAtInterfacesLikeTheWalk) {
    MediumParams shell, core;
    shell.sigmaA = RGB(0.4, 0.5, 0.6);
    core.sigmaA = RGB(0.9, 0.2, 0.1);
    shell.sigmaS = core.sigmaS = RGB(0);
    Volume volume = nestedSpheres(shell, core);
    expectSameAsTheWalk(volume, 6);  // crossing the interface: the walk goes on there
    stopAtInterfaces(volume);
    expectSameAsTheWalk(volume, 7);  // stopping there: the exit is the interface
}

// Flights that jump (sampleFlight with jump: one exit query, the interaction placed directly)
// against the walk of every tet, from the tet of the origin and from another tet of its region
// (WalkStart::inRegion): the same interaction or exit, the same transmittance, to the last bits.
// Shadow rays and transmittance from a point in a region agree with those from its tet.
void expectJumpsAsTheWalk(Volume& volume, uint64_t seed) {
    const TetMesh& mesh = volume.mesh();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
    size_t jumped = 0, left = 0, flights = 0, entering = 0, enteredAndJumped = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 p(0.9 * u(rng), 0.9 * u(rng), 0.9 * u(rng));
        const int64_t tet = volume.traversal().locate(p);
        if (tet < 0) continue;
        uint32_t hint = uint32_t(rng() % mesh.tets.size());
        while (mesh.region(hint) != mesh.region(uint32_t(tet))) hint = uint32_t(rng() % mesh.tets.size());
        const Ray ray{p, test::onSphere(rng, 1)};
        const double v = u01(rng);
        const int hero = int(rng() % 3);
        ExitQueryAccess::setExitQueryAfter(volume, 0);
        const FreeFlight walked = sampleFlight(volume, ray, WalkStart::inside(uint32_t(tet)), INFINITY, hero, v);
        for (const WalkStart start : {WalkStart::inside(uint32_t(tet)), WalkStart::inRegion(hint)}) {
            ++flights;
            const FreeFlight f = sampleFlight(volume, ray, start, INFINITY, hero, v, RGB(1), true);
            ASSERT_EQ(f.scattered, walked.scattered);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(f.transmittance[c], walked.transmittance[c], 1e-12);
            if (f.scattered) {
                ASSERT_NEAR(f.t, walked.t, 1e-12);
                ASSERT_EQ(mesh.region(f.tet), mesh.region(walked.tet));
                if (f.located) {
                    ASSERT_EQ(f.tet, walked.tet);
                }
                jumped += !f.located;
            } else {
                ASSERT_EQ(f.exit.left, walked.exit.left);
                ASSERT_EQ(f.exit.triangle, walked.exit.triangle);
                ASSERT_EQ(f.exit.tet, walked.exit.tet);
                ASSERT_NEAR(f.exit.t, walked.exit.t, 1e-12);
                left += f.exit.left;
            }
        }
        // The same flight from outside, entering through the surface on the way to p.
        const Ray from{p - 3.0 * ray.d, ray.d};
        if (const auto entry = volume.traversal().firstEntry(from, 0, INFINITY)) {
            const WalkStart surface = WalkStart::surface(entry->entryTriangle());
            const FreeFlight w = sampleFlight(volume, from, surface, INFINITY, hero, v);
            const FreeFlight f = sampleFlight(volume, from, surface, INFINITY, hero, v, RGB(1), true);
            ++entering;
            ASSERT_EQ(f.scattered, w.scattered);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(f.transmittance[c], w.transmittance[c], 1e-12);
            if (f.scattered) {
                ASSERT_NEAR(f.t, w.t, 1e-12);
                ASSERT_EQ(mesh.region(f.tet), mesh.region(w.tet));
                enteredAndJumped += !f.located;
            } else {
                ASSERT_EQ(f.exit.triangle, w.exit.triangle);
                ASSERT_NEAR(f.exit.t, w.exit.t, 1e-12);
            }
        }
        ExitQueryAccess::setExitQueryAfter(volume, 1);
        Rng r0(7, uint64_t(i)), r1(7, uint64_t(i));
        const FreeFlight fromTet = shadowFlight(volume, ray, WalkStart::inside(uint32_t(tet)), INFINITY, r0);
        const FreeFlight fromRegion = shadowFlight(volume, ray, WalkStart::inRegion(hint), INFINITY, r1);
        ASSERT_EQ(fromRegion.exit.triangle, fromTet.exit.triangle);
        ASSERT_NEAR(fromRegion.exit.t, fromTet.exit.t, 1e-12);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(fromRegion.transmittance[c], fromTet.transmittance[c], 1e-12);
        const RGB tr = transmittance(volume, ray, WalkStart::inRegion(hint), INFINITY),
                  trTet = transmittance(volume, ray, WalkStart::inside(uint32_t(tet)), INFINITY);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(tr[c], trTet[c], 1e-12);
    }
    std::printf("%zu flights: %zu jumped to an interaction, %zu left the medium; %zu entering, %zu of them jumped\n",
                flights, jumped, left, entering, enteredAndJumped);
    EXPECT_GT(jumped, flights / 8);
    EXPECT_GT(left, flights / 10);
    EXPECT_GT(enteredAndJumped, entering / 8);
}

TEST(RegionMediaExit, FlightsThatJumpLandWhereTheWalkLands) {
    // Thin enough that flights jump: a mean free path of more than 16 mean tet chords.
    MediumParams p;
    p.sigmaA = RGB(0.1, 0.15, 0.2);
    p.sigmaS = RGB(0.35, 0.3, 0.25);
    auto volume = std::make_unique<Volume>(p, tetrahedralize(icosphere(3), test::noCache()));
    expectJumpsAsTheWalk(*volume, 8);
}

TEST(RegionMediaExit, FlightsThatJumpCrossOrStopAtInterfacesLikeTheWalk) {
    Volume volume = scatteringNestedSpheres();
    expectJumpsAsTheWalk(volume, 9);
    stopAtInterfaces(volume);
    expectJumpsAsTheWalk(volume, 10);
}

// A stretch (regionStretch: one exit query) ends where the walk of every tet leaves
// its region: whole, with the walk's exit triangle, tet and t, where the walk leaves the medium or
// stops at an interface; not whole where the ray goes on across an interface into another region
// or where the exit lies beyond the depth the stretch looks ahead.
void expectStretchesEndAsTheWalk(Volume& volume, uint64_t seed, bool crosses) {
    std::mt19937_64 rng(seed);
    size_t whole = 0, across = 0, short_ = 0, unsure = 0;
    for (int i = 0; i < 1000; ++i) {
        const auto drawn = interiorRay(volume, rng);
        if (!drawn) continue;
        const auto [ray, tet] = *drawn;
        const WalkStart start = WalkStart::inside(uint32_t(tet));
        const int32_t region = volume.mesh().region(uint32_t(tet));
        // The walk's way out of the region: its segments until the region changes.
        double leaves = INFINITY;
        bool intoAnother = false;
        const TetWalk walk = volume.walk(ray, start, [&](const WalkSegment& s) {
            if (volume.mesh().region(s.tet) == region) return true;
            leaves = s.tIn;
            intoAnother = true;
            return false;
        });
        if (!intoAnother) leaves = walk.exitT();
        const auto stretch = regionStretch(volume, ray, start, INFINITY, 1e6);
        if (!stretch) {  // too close to call (an exit just ahead): the walk decides
            ++unsure;
            continue;
        }
        ASSERT_NEAR(stretch->end, leaves, 1e-12);
        ASSERT_EQ(stretch->whole, !intoAnother);
        if (stretch->whole) {
            ++whole;
            ASSERT_TRUE(stretch->exit.left);
            ASSERT_EQ(stretch->exit.triangle, walk.exitTriangle());
            ASSERT_EQ(stretch->exit.tet, walk.exitTet());
        }
        across += intoAnother;
        // Looking ahead a tenth of the way: the end is that far, not known beyond.
        const RGB& sigma = volume.at(uint32_t(tet)).sigmaT;
        const double least = std::min({sigma.x, sigma.y, sigma.z});
        const auto near = regionStretch(volume, ray, start, INFINITY, 0.1 * least * leaves);
        if (!near) continue;
        ASSERT_FALSE(near->whole);
        ASSERT_NEAR(near->end, 0.1 * leaves, 1e-12);
        ++short_;
    }
    EXPECT_GT(whole, 300u);
    if (crosses) {
        EXPECT_GT(across, 50u);
    } else {
        EXPECT_EQ(across, 0u);
    }
    EXPECT_GT(short_, 400u);
    EXPECT_LT(unsure, 5u);
}

TEST(RegionMediaExit, AStretchEndsWhereTheWalkLeavesItsRegion) {
    MediumParams p;
    p.sigmaA = RGB(0.2, 0.3, 0.4);
    p.sigmaS = RGB(0.3);
    auto sphere = std::make_unique<Volume>(p, tetrahedralize(icosphere(3), test::noCache()));
    expectStretchesEndAsTheWalk(*sphere, 11, false);
    Volume nested = scatteringNestedSpheres();
    expectStretchesEndAsTheWalk(nested, 12, true);  // across the interface: not whole there
    stopAtInterfaces(nested);
    expectStretchesEndAsTheWalk(nested, 13, false);  // stopping there: whole, the interface its exit
}

TEST(RegionMediaExit, VaryingDensityKeepsTheWalk) {
    MediumParams p;
    p.sigmaA = RGB(1);
    TetMesh mesh = tetrahedralize(icosphere(2), test::noCache());
    std::vector<double> density(mesh.vertices.size());
    for (size_t v = 0; v < density.size(); ++v) density[v] = 1 + mesh.vertices[v].x;
    const Volume volume(p, std::move(mesh), density);
    const uint64_t queries = surfaceQueries();
    const int64_t tet = volume.traversal().locate(glm::dvec3(0.1, 0.2, 0.3));
    ASSERT_GE(tet, 0);
    transmittance(volume, {{0.1, 0.2, 0.3}, {1, 0, 0}}, WalkStart::inside(uint32_t(tet)), INFINITY);
    EXPECT_EQ(surfaceQueries(), queries);
}

// A path that leaves a convex medium cannot meet it again: the scene asks no surface query for
// it (FrontExtent), where without the triangle it left through it searches the rest of the ray.
TEST(RegionMediaExit, APathLeavingAConvexMediumAsksNoQueryToMeetItAgain) {
    const Scene scene(test::sceneWith(test::sphereMedium(RGB(0.1), RGB(0.5)), 8));
    std::mt19937_64 rng(41);
    int left = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 p(0.3, -0.2, 0.1);
        Ray ray{p, test::onSphere(rng, 1)};
        VolumeState state = scene.volumeAt(p);
        ASSERT_TRUE(state.inside());
        std::optional<Intersection> hit = scene.intersect(ray, state);
        const FreeFlight flight = sampleFlight(*scene.volumes()[0].volume, ray, state.start, INFINITY, 0, 1.0);
        ASSERT_EQ(endStretch(scene, hit, flight.exit, ray, state), StretchEnd::Crossed);
        ASSERT_FALSE(state.inside());
        ++left;
        const uint64_t queries = surfaceQueries();
        EXPECT_FALSE(scene.intersect(ray, state).has_value());
        EXPECT_EQ(surfaceQueries(), queries) << "ray " << i;
        EXPECT_FALSE(scene.intersect(ray, VolumeState{}).has_value());
        EXPECT_GT(surfaceQueries(), queries) << "ray " << i << ": the search without the bound";
    }
    EXPECT_EQ(left, 200);
}

}  // namespace
}  // namespace tetglow
