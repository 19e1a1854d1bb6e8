// Properties of the tetrahedralization and the walks, on the demo fish and on blub, spot and
// bob when ../shared/meshes is present.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "scene/MeshFile.h"
#include "tet/FrontExtent.h"
#include "tet/Predicates.h"
#include "tet/Shapes.h"
#include "tet/TetTraversal.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

// The medium's length along the ray from Embree's boundary hits: the ray is cut at every hit
// (t refined in double), at every end of a walk segment and at `extra`, and each piece counts
// when its midpoint is inside by the parity test (majority of 5 rays). Embree can report a
// crossing twice, or miss it, exactly at a vertex; the cuts make that harmless.
double embreeChord(const SurfaceBVH& bvh, const Ray& ray, std::vector<double> cuts, double merge) {
    for (const auto& h : bvh.allHits(ray)) cuts.push_back(h.t);
    std::sort(cuts.begin(), cuts.end());
    double length = 0, last = -INFINITY;
    std::vector<double> ts;
    for (double t : cuts)
        if (t - last > merge) ts.push_back(last = t);
    for (size_t i = 0; i + 1 < ts.size(); ++i)
        if (insideByParity(bvh, ray.at(0.5 * (ts[i] + ts[i + 1])), 5)) length += ts[i + 1] - ts[i];
    return length;
}

struct WalkResult {
    double length = 0;
    size_t steps = 0;
    bool ok = true;
    std::vector<double> ends;  // where segments start and stop
};

WalkResult walk(const TetTraversal& volume, const Ray& ray) {
    WalkResult r;
    r.ok = volume.traverse(
        ray, 0, INFINITY,
        [&](const WalkSegment& s) {
            r.length += s.tOut - s.tIn;
            ++r.steps;
            r.ends.push_back(s.tIn);
            r.ends.push_back(s.tOut);
            return true;
        },
        TetTraversal::kOutside);
    return r;
}

glm::dvec3 uniformDirection(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), s = std::sqrt(1 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
}

class TetCore : public testing::TestWithParam<test::NamedMesh> {
protected:
    void SetUp() override {
        if (GetParam().path.empty()) GTEST_SKIP() << GetParam().name << ".obj not tested: ../shared/meshes not found";
        volume_ = std::make_unique<TetTraversal>(tetrahedralize(readMesh(GetParam().path), test::noCache()));
        Bounds3 b;
        for (const auto& v : mesh().vertices) b.extend(v);
        bounds_ = b;
        diag_ = b.diagonal();
    }
    const TetMesh& mesh() const { return volume_->mesh(); }

    std::unique_ptr<TetTraversal> volume_;
    Bounds3 bounds_;
    double diag_ = 0;
};

TEST_P(TetCore, VolumeMatchesSurface) {
    const double surface = mesh().surfaceVolume(), tets = mesh().volume();
    EXPECT_GT(surface, 0);
    EXPECT_NEAR(tets, surface, 1e-9 * surface);
}

TEST_P(TetCore, TetsArePositivelyOrientedAndCompact) {
    const auto& m = mesh();
    for (uint32_t t = 0; t < m.tets.size(); ++t) {
        const auto& v = m.tets[t];
        ASSERT_LT(orient3d(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], m.vertices[v[3]]), 0) << "tet " << t;
    }
    EXPECT_LE(m.bytesPerTet(), 32u);
}

TEST_P(TetCore, NeighboursAreReciprocal) {
    const auto& m = mesh();
    for (uint32_t t = 0; t < m.tets.size(); ++t)
        for (int j = 0; j < 4; ++j) {
            const int32_t adj = m.adjacency[t][j];
            if (TetMesh::isBoundary(adj)) continue;
            const uint32_t n = TetMesh::neighbourTet(adj);
            const int k = TetMesh::neighbourFace(adj);
            ASSERT_EQ(m.adjacency[n][k], int32_t(4 * t + j)) << "tet " << t << " face " << j;
            // The shared face has the same three vertices seen from both sides.
            std::array<uint32_t, 3> a, b;
            for (int i = 0; i < 3; ++i) a[i] = m.tets[t][kInwardFace[j][i]], b[i] = m.tets[n][kInwardFace[k][i]];
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            ASSERT_EQ(a, b);
        }
}

TEST_P(TetCore, BoundaryFacesAreSurfaceTrianglesOneToOne) {
    const auto& m = mesh();
    const TriangleMesh input = [&] {
        TriangleMesh s = readMesh(GetParam().path);
        validateAndRepair(s);
        return s;
    }();
    ASSERT_EQ(m.surface.size(), input.triangles.size());
    std::vector<int> seen(m.surface.size(), 0);
    size_t boundaryFaces = 0;
    for (uint32_t t = 0; t < m.tets.size(); ++t)
        for (int j = 0; j < 4; ++j) {
            const int32_t adj = m.adjacency[t][j];
            if (!TetMesh::isBoundary(adj)) continue;
            ++boundaryFaces;
            const uint32_t s = TetMesh::surfaceTriangle(adj);
            ASSERT_LT(s, m.surface.size());
            ++seen[s];
            EXPECT_EQ(m.surfaceFace[s], 4 * t + j);
            // Same corners, bit for bit, as the input triangle; wound outward.
            std::array<uint32_t, 3> face, tri = m.surface[s];
            for (int i = 0; i < 3; ++i) face[i] = m.tets[t][kInwardFace[j][i]];
            for (int i = 0; i < 3; ++i) EXPECT_EQ(m.vertices[tri[i]], input.positions[input.triangles[s][i]]);
            std::sort(face.begin(), face.end());
            std::sort(tri.begin(), tri.end());
            EXPECT_EQ(face, tri);
        }
    EXPECT_EQ(boundaryFaces, m.surface.size());
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
}

TEST_P(TetCore, LocationAgreesWithParity) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const TriangleMesh surface = mesh().surfaceMesh();
    int disagreements = 0, inside = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::dvec3 p = bounds_.lo + (bounds_.hi - bounds_.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const int64_t t = volume_->locate(p);
        inside += t >= 0;
        if (t >= 0) {
            ASSERT_TRUE(volume_->contains(uint32_t(t), p));  // the answer really holds p
        }
        if ((t >= 0) == insideByParity(volume_->bvh(), p, 5)) continue;
        // Only points within 1e-6 of the diagonal from the surface may disagree.
        double d = INFINITY;
        for (uint32_t s = 0; s < surface.triangles.size(); ++s) {
            const glm::dvec3 a = surface.corner(s, 0),
                             n = glm::normalize(glm::cross(surface.corner(s, 1) - a, surface.corner(s, 2) - a));
            d = std::min(d, std::abs(glm::dot(p - a, n)));
        }
        EXPECT_LT(d, 1e-6 * diag_) << "point " << p.x << ' ' << p.y << ' ' << p.z;
        ++disagreements;
    }
    EXPECT_GT(inside, 1000);
    EXPECT_LT(disagreements, 10);
}

TEST_P(TetCore, RandomRayChordsMatchEmbree) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    size_t maxSteps = 0;
    int hitting = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::dvec3 target = bounds_.lo + (bounds_.hi - bounds_.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const glm::dvec3 d = uniformDirection(rng);
        const Ray ray{target - d * diag_, d};
        const WalkResult w = walk(*volume_, ray);
        ASSERT_TRUE(w.ok) << "walk lost on ray " << i;
        const double ref = embreeChord(volume_->bvh(), ray, w.ends, 1e-9 * diag_);
        ASSERT_NEAR(w.length, ref, 1e-6 * diag_) << "ray " << i;
        hitting += ref > 0;
        maxSteps = std::max(maxSteps, w.steps);
    }
    EXPECT_GT(hitting, 10000);
    EXPECT_LE(maxSteps, mesh().tets.size());
}

// The chord of a ray exactly from the surface triangles, for rays through vertices and edges
// where Embree's float hits cannot serve: it misses crossings exactly through a vertex, reports
// some twice, and a ray that runs in the surface has no inside or outside for the parity test.
// Each triangle is crossed or not by exact orientation tests in the plane across the ray, with
// the walk's tie-break (simulation of simplicity: the ray moved by an infinitesimal that is the
// same for every triangle, so the crossings are those of one line, alternately in and out); the
// chord is the sum of the exits' t less the sum of the entries' t (the rays start outside the
// bounds, so every crossing has t > 0). Tets and Embree play no part; only side() is shared
// with the walk. Also the clearance: how far the ray passes from the nearest surface edge or vertex.
struct ExactChord {
    double chord = 0, clearance = INFINITY;
};

ExactChord exactChord(const TetMesh& m, const Ray& ray) {
    const RayProjection project(ray);
    std::vector<RayProjection::Point> p(m.surfaceVertexCount);
    for (uint32_t i = 0; i < p.size(); ++i) p[i] = project(m.vertices[i]);
    // The distance from the ray (the projection's origin) to the projected segment a-b.
    const auto distance = [](const glm::dvec2& a, const glm::dvec2& b) {
        const glm::dvec2 e = b - a;
        const double s = glm::dot(e, e) > 0 ? glm::clamp(-glm::dot(a, e) / glm::dot(e, e), 0.0, 1.0) : 0.0;
        return glm::length(a + s * e);
    };
    ExactChord r;
    for (const auto& f : m.surface) {
        const auto &a = p[f[0]], &b = p[f[1]], &c = p[f[2]];
        r.clearance = std::min({r.clearance, distance(a.uv, b.uv), distance(b.uv, c.uv), distance(c.uv, a.uv)});
        const double ab = side(f[0], a.uv, f[1], b.uv), bc = side(f[1], b.uv, f[2], c.uv),
                     ca = side(f[2], c.uv, f[0], a.uv);
        if ((ab > 0) != (bc > 0) || (bc > 0) != (ca > 0)) continue;
        const double t = (bc * a.t + ca * b.t + ab * c.t) / (ab + bc + ca);  // barycentric in the projection
        r.chord += ab > 0 ? t : -t;  // counter-clockwise: the outward normal points along the ray, an exit
    }
    return r;
}

// The chord from Embree's hits: the exits' t less the entries' t.
double embreeHitChord(const SurfaceBVH& bvh, const Ray& ray) {
    double chord = 0;
    for (const SurfaceHit& h : bvh.allHits(ray)) chord += h.entering ? -h.t : h.t;
    return chord;
}

// Rays exactly through vertices, along interior tet edges and through edge midpoints: the
// cases where sign tests are exactly zero and only the tie-break keeps the walk consistent.
// The reference is Embree where it is unambiguous, where the ray passes farther than 1e-6
// diagonals (ten times Embree's float error) from every surface edge and vertex, so that each
// crossing is through a triangle's interior; exactChord otherwise. Rays along a
// surface edge are left out: their chord is undefined (rays on either side differ by the
// edge, and rounding the projection decides which side the walk takes).
TEST_P(TetCore, DegenerateRayChordsMatchEmbreeOrExactChord) {
    const auto& m = mesh();
    std::mt19937_64 rng(5);
    const size_t stride = std::max<size_t>(1, m.vertices.size() / 3000);
    int rays = 0, ambiguous = 0, lost = 0, longWalks = 0, off = 0;
    std::set<std::pair<uint32_t, uint32_t>> surfaceEdges;
    for (const auto& f : m.surface)
        for (int k = 0; k < 3; ++k) surfaceEdges.insert(std::minmax(f[k], f[(k + 1) % 3]));
    auto check = [&](const Ray& ray) {
        const WalkResult w = walk(*volume_, ray);
        const double length = glm::length(ray.d);
        const ExactChord exact = exactChord(m, ray);
        const bool embreeValid = exact.clearance > 1e-6 * diag_;
        const double ref = embreeValid ? embreeHitChord(volume_->bvh(), ray) : exact.chord;
        ambiguous += !embreeValid;
        ++rays;
        lost += !w.ok;
        longWalks += w.steps > m.tets.size();
        const bool wrong = w.ok && std::abs(w.length - ref) * length > 1e-6 * diag_;
        off += wrong;
        EXPECT_FALSE(wrong) << "walk " << w.length << " reference " << ref << " on ray o " << ray.o.x << ' ' << ray.o.y
                            << ' ' << ray.o.z << " d " << ray.d.x << ' ' << ray.d.y << ' ' << ray.d.z;
    };
    std::vector<std::vector<uint32_t>> ring(m.vertices.size());  // surface neighbours
    for (const auto& [a, b] : surfaceEdges) {
        ring[a].push_back(b);
        ring[b].push_back(a);
    }
    for (size_t v = 0; v < m.vertices.size(); v += stride)
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 d(0);
            d[axis] = 1;  // axis-aligned from outside: the line passes exactly through the vertex
            const bool alongEdge = std::any_of(ring[v].begin(), ring[v].end(), [&](uint32_t w) {
                const glm::dvec3 e = m.vertices[w] - m.vertices[v];
                return e[(axis + 1) % 3] == 0 && e[(axis + 2) % 3] == 0;
            });
            if (!alongEdge) check({m.vertices[v] - d * (2 * diag_), d});
        }
    for (size_t t = 0; t < m.tets.size(); t += std::max<size_t>(1, m.tets.size() / 3000)) {
        const int i = int(rng() % 4), j = (i + 1 + int(rng() % 3)) % 4;
        const glm::dvec3 a = m.vertices[m.tets[t][i]], b = m.vertices[m.tets[t][j]];
        const glm::dvec3 d = b - a;  // exact for float vertices: the line holds a and b exactly
        const double back = std::ldexp(1.0, int(std::ceil(std::log2(2 * diag_ / glm::length(d)))));
        if (!surfaceEdges.count(std::minmax(m.tets[t][i], m.tets[t][j]))) check({a - d * back, d});
        glm::dvec3 axis(0);
        axis[int(rng() % 3)] = 1;
        check({(a + b) * 0.5 - axis * (2 * diag_), axis});
    }
    std::printf(
        "degenerate rays on %s: %d (exact reference for %d where Embree is ambiguous), lost %d, "
        "more steps than tets %d, chord off by > 1e-6 diagonals %d\n",
        GetParam().name.c_str(), rays, ambiguous, lost, longWalks, off);
    EXPECT_GT(rays, 3000);
    EXPECT_EQ(lost + longWalks + off, 0);  // each counted on the line above
}

// A ray leaving through a surface triangle meets the medium again, if at all, before the
// triangle's FrontExtent bound: rays from random points of random triangles in random outward
// directions, the first re-entry by the exact search along the whole ray.
TEST_P(TetCore, NoReentryBeyondTheFrontExtent) {
    const auto& m = mesh();
    const FrontExtent front(m);
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0, 1);
    int reentries = 0, bounded = 0, none = 0;
    for (int i = 0; i < 4000; ++i) {
        const uint32_t s = uint32_t(rng() % m.surface.size());
        const auto& f = m.surface[s];
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const glm::dvec3 p0 = m.vertices[f[0]], p1 = m.vertices[f[1]], p2 = m.vertices[f[2]];
        const glm::dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
        glm::dvec3 d = uniformDirection(rng);
        if (glm::dot(d, n) < 0) d = -d;
        const Ray ray{p0 + a * (p1 - p0) + b * (p2 - p0), d};
        const double bound = front.reentryBefore(s, ray);
        bounded += std::isfinite(bound);
        none += bound < 1e-6 * diag_;
        if (const auto entry = volume_->firstEntry(ray, 1e-9 * diag_, INFINITY)) {
            ++reentries;
            ASSERT_LE(entry->exitT(), bound) << "triangle " << s << " ray " << i;
        }
    }
    std::printf("%s: %d re-entries, all before the bound; %d of 4000 bounded, %d with no re-entry possible\n",
                GetParam().name.c_str(), reentries, bounded, none);
    EXPECT_GT(reentries, 100);
    EXPECT_GT(bounded, 3000);
}

TEST(FrontExtent, NothingLiesInFrontOfAConvexSurface) {
    const TetMesh mesh = tetrahedralize(icosphere(3), test::noCache());
    const FrontExtent front(mesh);
    std::mt19937_64 rng(31);
    for (uint32_t s = 0; s < mesh.surface.size(); ++s) {
        const auto& f = mesh.surface[s];
        const glm::dvec3 c = (mesh.vertices[f[0]] + mesh.vertices[f[1]] + mesh.vertices[f[2]]) / 3.0;
        glm::dvec3 d = uniformDirection(rng);
        if (glm::dot(d, c) < 0) d = -d;  // outward, near enough: the sphere's normal is c's direction
        const double bound = front.reentryBefore(s, Ray{c, d});
        if (glm::dot(d, glm::normalize(c)) > 0.1) {
            ASSERT_LT(bound, 1e-6) << "triangle " << s;
        }
    }
}

// visitCandidates stops Embree's search past the t its visitor names: every candidate before it
// must still be visited, whenever Embree finds them. The visitor names a t midway along the
// candidates from its first call on.
TEST_P(TetCore, VisitedCandidatesHoldEveryOneBeforeTheLimit) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    size_t checked = 0, skipped = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 target = bounds_.lo + (bounds_.hi - bounds_.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const glm::dvec3 d = uniformDirection(rng);
        const Ray ray{target - d * diag_, d};
        std::vector<SurfaceHit> all = volume_->bvh().candidates(ray);
        if (all.size() < 2) continue;
        std::sort(all.begin(), all.end(), [](const SurfaceHit& a, const SurfaceHit& b) { return a.t < b.t; });
        const double limit = all[all.size() / 2 - 1].t;
        std::set<uint32_t> visited;
        volume_->bvh().visitCandidates(ray, 0, INFINITY, [&](const SurfaceHit& c) {
            visited.insert(c.triangle);
            return limit;
        });
        for (const SurfaceHit& c : all) {
            if (c.t <= limit) {
                ASSERT_TRUE(visited.count(c.triangle)) << "ray " << i << ": candidate at t " << c.t << " missed";
            }
        }
        checked += all.size();
        skipped += all.size() - visited.size();
    }
    std::printf("%s: %zu candidates, %zu past the limit not searched\n", GetParam().name.c_str(), checked, skipped);
    EXPECT_GT(skipped, checked / 10);  // Embree stops at the limit its filter set
}

// firstEntry stops searching past the first entry it finds; traverse() asks every candidate
// along the ray. Both must begin at the same entry, in the same tet, from outside and from past
// the end of each chord (where the ray may enter again), on random rays and on rays through
// vertices along the axes, where Embree's float tests are least sure.
TEST_P(TetCore, FirstEntryIsTheFirstOfAllEntries) {
    const auto& m = mesh();
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 target = bounds_.lo + (bounds_.hi - bounds_.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const glm::dvec3 d = uniformDirection(rng);
        rays.push_back({target - d * diag_, d});
    }
    for (size_t v = 0; v < m.surfaceVertexCount; v += std::max<size_t>(1, m.surfaceVertexCount / 1000)) {
        glm::dvec3 d(0);
        d[int(v % 3)] = 1;
        rays.push_back({m.vertices[v] - d * (2 * diag_), d});
    }
    // An entry whose walk leaves at once (the ray touches the medium at a vertex or an edge)
    // gives traverse() no segment.
    auto leadsStraightOut = [](TetWalk w) {
        for (WalkSegment s; w.next(s);)
            if (s.tOut > s.tIn) return false;
        return true;
    };
    int entries = 0, reentries = 0;
    for (const Ray& ray : rays) {
        // The chords traverse() walks from outside, each from its first segment to its end.
        std::vector<std::pair<WalkSegment, double>> chords;
        volume_->traverse(
            ray, 0, INFINITY,
            [&](const WalkSegment& s) {
                if (chords.empty() || s.tIn != chords.back().second)
                    chords.push_back({s, s.tOut});
                else
                    chords.back().second = s.tOut;
                return true;
            },
            TetTraversal::kOutside);
        double tnear = 0;
        for (const auto& [start, end] : chords) {
            auto first = volume_->firstEntry(ray, tnear, INFINITY);
            while (first && first->exitT() < start.tIn && leadsStraightOut(*first))
                first = volume_->firstEntry(ray, std::nextafter(first->exitT(), INFINITY), INFINITY);
            ASSERT_TRUE(first.has_value()) << "no entry found for the chord from t " << start.tIn;
            ASSERT_EQ(first->exitT(), start.tIn);
            if (!leadsStraightOut(*first)) {
                ASSERT_EQ(first->exitTet(), start.tet);
            }
            ++(tnear == 0 ? entries : reentries);
            tnear = end;
        }
    }
    std::printf("%s: %zu rays, %d entries and %d re-entries the same\n", GetParam().name.c_str(), rays.size(), entries,
                reentries);
    EXPECT_GT(entries, 1000);
}

TEST_P(TetCore, WalkFromInsideMatchesWalkFromOutside) {
    // Starting at a located interior point gives the same exit as entering from outside.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    int tested = 0;
    while (tested < 2000) {
        const glm::dvec3 p = bounds_.lo + (bounds_.hi - bounds_.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const int64_t t = volume_->locate(p);
        if (t < 0) continue;
        const glm::dvec3 d = uniformDirection(rng);
        const Ray ray{p - d * (2 * diag_), d};
        double inner = 0, outer = 0;
        volume_->traverse(
            ray, 2 * diag_, INFINITY,
            [&](const WalkSegment& s) {
                inner += s.tOut - s.tIn;
                return true;
            },
            t);
        volume_->traverse(
            ray, 2 * diag_, INFINITY,
            [&](const WalkSegment& s) {
                outer += s.tOut - s.tIn;
                return true;
            },
            TetTraversal::kUnknown);
        double full = 0;
        volume_->traverse(
            ray, 0, INFINITY,
            [&](const WalkSegment& s) {
                if (s.tOut > 2 * diag_) full += s.tOut - std::max(s.tIn, 2 * diag_);
                return true;
            },
            TetTraversal::kOutside);
        ASSERT_NEAR(inner, full, 1e-6 * diag_);
        ASSERT_NEAR(outer, full, 1e-6 * diag_);
        ++tested;
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, TetCore, testing::ValuesIn(test::referenceMeshes()), test::meshName);

}  // namespace
}  // namespace tetglow

namespace tetglow {
namespace {

TEST(TetWalkDegenerate, BodyDiagonalThroughAPinch) {
    // Two cubes touching at one corner; the diagonal along (1, 1, 1) passes exactly through
    // both outer corners and the pinch, where the walk leaves one shell and must find the next.
    TetOptions o;
    o.useCache = false;
    const TetTraversal volume(tetrahedralize(merge(box(), box(glm::dvec3(1), glm::dvec3(2))), o));
    for (const double s : {1.0, -1.0}) {
        const glm::dvec3 d(s, s, s);
        const Ray ray{glm::dvec3(1) - 2.0 * d, d};  // through the cubes for t in [1, 3]
        double length = 0;
        ASSERT_TRUE(volume.traverse(
            ray, 0, INFINITY,
            [&](const WalkSegment& w) {
                length += w.tOut - w.tIn;
                return true;
            },
            TetTraversal::kOutside));
        EXPECT_NEAR(length, 2.0, 1e-6);
    }
}

// A max volume TetGen cannot meet without splitting the boundary: a unit box stays 12 tets at
// 0.001, which was silent; now it is said. An icosphere of radius 1 at 0.01 meets it.
TEST(TetOptions, MaxVolumeTetGenCannotMeetIsReported) {
    TetOptions options;
    options.useCache = false;
    options.maxVolume = 0.001;
    TetStats stats;
    const TetMesh cube = tetrahedralize(box(), options, &stats);
    EXPECT_EQ(
        stats.maxVolumeWarning.rfind(std::to_string(cube.tets.size()) + " of " + std::to_string(cube.tets.size()) +
                                         " tets are larger than the max volume 0.001",
                                     0),
        0u)
        << stats.maxVolumeWarning;
    options.maxVolume = 0.01;
    const TetMesh sphere = tetrahedralize(icosphere(3), options, &stats);
    EXPECT_GT(sphere.tets.size(), 4.0 / 0.01);
    EXPECT_EQ(stats.maxVolumeWarning, "");
}

}  // namespace
}  // namespace tetglow
