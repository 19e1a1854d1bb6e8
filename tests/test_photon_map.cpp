// The photon map's k-NN and radius queries, assignRadii and the beam BVH, each against brute
// force over every photon; direction packing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "photon/OctahedralDirection.h"
#include "photon/PhotonDiscs.h"
#include "photon/PhotonMap.h"

namespace tetglow {
namespace {

constexpr size_t kPhotons = 20000;
constexpr int kQueries = 1000;

// Uniform in the unit cube, or 30% uniform and the rest in 12 tight Gaussian clusters, with
// every 50th photon a copy of its predecessor (equal distances).
std::vector<Photon> makePhotons(size_t n, bool clustered, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> u(0, 1);
    std::normal_distribution<float> g(0, 0.02f);
    std::vector<glm::vec3> centres(12);
    for (auto& c : centres) c = {u(rng), u(rng), u(rng)};
    std::vector<Photon> photons(n);
    for (size_t i = 0; i < n; ++i) {
        glm::vec3 p(u(rng), u(rng), u(rng));
        if (clustered && u(rng) > 0.3f) p = centres[rng() % centres.size()] + glm::vec3(g(rng), g(rng), g(rng));
        if (clustered && i % 50 == 49) p = photons[i - 1].position;
        photons[i] = {p, glm::vec3(1), packDirection(glm::vec3(0, 0, 1)), 0};
    }
    return photons;
}

// Summed in nanoflann's order, so that distances compare exactly.
float distance2(const glm::vec3& q, const glm::vec3& p) {
    const glm::vec3 d = q - p;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

// The `keep` nearest with distance2 < maxDistance2, by distance then index.
std::vector<Neighbour> bruteForce(const std::vector<Photon>& photons, const glm::vec3& q, float maxDistance2,
                                  size_t keep = SIZE_MAX) {
    std::vector<Neighbour> all;
    for (uint32_t i = 0; i < photons.size(); ++i)
        if (const float d2 = distance2(q, photons[i].position); d2 < maxDistance2) all.push_back({i, d2});
    keep = std::min(keep, all.size());
    std::partial_sort(all.begin(), all.begin() + ptrdiff_t(keep), all.end(),
                      [](const Neighbour& a, const Neighbour& b) {
                          return a.distance2 != b.distance2 ? a.distance2 < b.distance2 : a.index < b.index;
                      });
    all.resize(keep);
    return all;
}

// The k nearest: same distances in the same order, distinct indices, each index truly at its
// distance. Photons tied at the k-th distance may be any of the tied ones.
void expectKnn(const std::vector<Photon>& photons, const glm::vec3& q, const std::vector<Neighbour>& got,
               std::vector<Neighbour> want, size_t k) {
    want.resize(std::min(want.size(), k));
    ASSERT_EQ(got.size(), want.size());
    std::set<uint32_t> seen;
    for (size_t i = 0; i < got.size(); ++i) {
        ASSERT_EQ(got[i].distance2, want[i].distance2) << "rank " << i;
        ASSERT_LT(got[i].index, photons.size());
        ASSERT_EQ(got[i].distance2, distance2(q, photons[got[i].index].position));
        EXPECT_TRUE(seen.insert(got[i].index).second);
    }
}

glm::vec3 randomQuery(std::mt19937_64& rng) {
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    return {u(rng), u(rng), u(rng)};
}

TEST(PhotonMap, KnnMatchesBruteForce) {
    for (bool clustered : {false, true}) {
        const std::vector<Photon> photons = makePhotons(kPhotons, clustered, 1);
        const PhotonMap map(photons);
        ASSERT_EQ(map.size(), kPhotons);
        std::mt19937_64 rng(2);
        std::vector<Neighbour> got;
        for (int q = 0; q < kQueries; ++q) {
            const glm::vec3 p = q % 10 == 0 ? photons[rng() % kPhotons].position : randomQuery(rng);
            const std::vector<Neighbour> all = bruteForce(photons, p, INFINITY, 200);
            for (int k : {1, 7, 50, 200}) {
                map.knn(p, k, got);
                expectKnn(photons, p, got, all, size_t(k));
            }
            const float maxDistance2 = 0.002f;  // the ball holds about 0-100 photons
            map.knn(p, 50, got, maxDistance2);
            expectKnn(photons, p, got, bruteForce(photons, p, maxDistance2), 50);
        }
    }
}

TEST(PhotonMap, KnnBeyondTheMapSize) {
    const std::vector<Photon> photons = makePhotons(40, true, 3);
    const PhotonMap map(photons);
    std::mt19937_64 rng(4);
    std::vector<Neighbour> got;
    for (int q = 0; q < kQueries; ++q) {
        const glm::vec3 p = randomQuery(rng);
        map.knn(p, 41 + q % 1000, got);
        expectKnn(photons, p, got, bruteForce(photons, p, INFINITY), photons.size());
        EXPECT_EQ(got.size(), photons.size());
    }
    map.knn(glm::vec3(0.5f), 0, got);
    EXPECT_TRUE(got.empty());
}

TEST(PhotonMap, WithinRadiusMatchesBruteForce) {
    for (bool clustered : {false, true}) {
        const std::vector<Photon> photons = makePhotons(kPhotons, clustered, 5);
        const PhotonMap map(photons);
        std::mt19937_64 rng(6);
        std::vector<Neighbour> got;
        for (int q = 0; q < kQueries; ++q) {
            const glm::vec3 p = q % 10 == 0 ? photons[rng() % kPhotons].position : randomQuery(rng);
            for (float radius : {0.0f, 0.01f, 0.04f, 0.15f}) {
                map.withinRadius(p, radius, got);
                const std::vector<Neighbour> want = bruteForce(photons, p, radius * radius);
                ASSERT_EQ(got.size(), want.size());
                for (size_t i = 0; i < got.size(); ++i) {
                    ASSERT_EQ(got[i].index, want[i].index);
                    ASSERT_EQ(got[i].distance2, want[i].distance2);
                }
            }
        }
    }
}

TEST(PhotonMap, ConcurrentReadersAgreeWithOne) {
    const std::vector<Photon> photons = makePhotons(kPhotons, true, 7);
    const PhotonMap map(photons);
    std::vector<std::vector<Neighbour>> serial(kQueries), parallel(kQueries);
    for (int q = 0; q < kQueries; ++q) map.knn(photons[size_t(q) * 13].position, 30, serial[size_t(q)]);
    tbb::parallel_for(0, kQueries, [&](int q) { map.knn(photons[size_t(q) * 13].position, 30, parallel[size_t(q)]); });
    for (int q = 0; q < kQueries; ++q)
        for (size_t i = 0; i < serial[size_t(q)].size(); ++i) {
            EXPECT_EQ(serial[size_t(q)][i].index, parallel[size_t(q)][i].index);
            EXPECT_EQ(serial[size_t(q)][i].distance2, parallel[size_t(q)][i].distance2);
        }
}

TEST(PhotonMap, AssignRadiiMatchesBruteForce) {
    const std::vector<Photon> photons = makePhotons(kPhotons, true, 8);
    const int k = 12;
    const float maxRadius = 0.03f;
    PhotonMap map(photons);
    map.assignRadii(k, maxRadius);
    int clamped = 0;
    for (size_t i = 0; i < kPhotons; i += 7) {
        // The photon itself comes first at distance 0; its k-th other photon is entry k.
        const std::vector<Neighbour> all = bruteForce(photons, photons[i].position, maxRadius * maxRadius);
        const float want = all.size() > size_t(k) ? std::sqrt(all[size_t(k)].distance2) : maxRadius;
        ASSERT_EQ(map.photons()[i].radius, want) << "photon " << i;
        clamped += want == maxRadius;
    }
    EXPECT_GT(clamped, 0);  // the clamp was exercised, and so were the neighbours
    EXPECT_LT(clamped, int(kPhotons / 7));

    PhotonMap again(photons);
    again.assignRadii(k, maxRadius);
    for (size_t i = 0; i < kPhotons; ++i) ASSERT_EQ(again.photons()[i].radius, map.photons()[i].radius);
}

TEST(PhotonMap, EmptyMap) {
    PhotonMap map({});
    std::vector<Neighbour> out{{1, 2}};
    map.knn(glm::vec3(0), 10, out);
    EXPECT_TRUE(out.empty());
    out.push_back({1, 2});
    map.withinRadius(glm::vec3(0), 1, out);
    EXPECT_TRUE(out.empty());
    map.assignRadii(5, 1);
    EXPECT_EQ(map.size(), 0u);

    const PhotonDiscs beams(map.photons());
    int visits = 0;
    beams.query(glm::dvec3(0), glm::dvec3(1, 0, 0), 0, INFINITY, [&](uint32_t, double, double) { ++visits; });
    EXPECT_EQ(visits, 0);
    EXPECT_EQ(beams.size(), 0u);
}

TEST(PhotonMap, MovedMapStillAnswers) {
    const std::vector<Photon> photons = makePhotons(500, false, 9);
    PhotonMap first(photons);
    const PhotonMap moved(std::move(first));
    std::vector<Neighbour> got;
    moved.knn(glm::vec3(0.5f), 5, got);
    expectKnn(photons, glm::vec3(0.5f), got, bruteForce(photons, glm::vec3(0.5f), INFINITY), 5);
}

struct BeamHit {
    uint32_t index;
    double t, distance2;
};

// By the cross product, independent of the query's residual-vector formula.
std::vector<BeamHit> bruteForceBeam(const std::vector<Photon>& photons, const glm::dvec3& o, const glm::dvec3& d,
                                    double tmin, double tmax) {
    std::vector<BeamHit> hits;
    for (uint32_t i = 0; i < photons.size(); ++i) {
        const glm::dvec3 v = glm::dvec3(photons[i].position) - o;
        const double t = glm::dot(v, d), r = photons[i].radius;
        const glm::dvec3 c = glm::cross(v, d);
        if (t >= tmin && t <= tmax && glm::dot(c, c) < r * r) hits.push_back({i, t, glm::dot(c, c)});
    }
    return hits;
}

TEST(PhotonMap, BeamQueryMatchesBruteForce) {
    std::vector<Photon> photons = makePhotons(kPhotons, true, 10);
    PhotonMap map(std::move(photons));
    map.assignRadii(20, 0.05f);
    photons = map.photons();
    for (size_t i = 0; i < photons.size(); i += 97) photons[i].radius = 0;  // no disc
    const PhotonDiscs beams(photons);
    EXPECT_EQ(beams.size(), photons.size() - (photons.size() + 96) / 97);

    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    size_t total = 0;
    for (int r = 0; r < kQueries; ++r) {
        glm::dvec3 o(u(rng) * 2 - 0.5, u(rng) * 2 - 0.5, u(rng) * 2 - 0.5), d;
        if (r % 4 == 0) {
            // Axis-parallel, and every other one straight through a photon.
            const int axis = r / 4 % 3;
            d = glm::dvec3(0);
            d[axis] = r % 8 == 0 ? 1 : -1;
            if (r % 8 == 4) o = glm::dvec3(photons[rng() % photons.size()].position) - 2.0 * d;
        } else {
            const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), s = std::sqrt(1 - z * z);
            d = {s * std::cos(phi), s * std::sin(phi), z};
        }
        double tmin = 0, tmax = INFINITY;
        if (r % 3 == 1) tmin = -INFINITY;
        if (r % 3 == 2) {  // clipped inside the cloud
            tmin = u(rng) * 1.5;
            tmax = tmin + u(rng) * 0.5;
        }
        std::vector<BeamHit> got;
        beams.query(o, d, tmin, tmax, [&](uint32_t index, double t, double distance2) {
            got.push_back({index, t, distance2});
        });
        const std::vector<BeamHit> want = bruteForceBeam(photons, o, d, tmin, tmax);
        std::sort(got.begin(), got.end(), [](const BeamHit& a, const BeamHit& b) { return a.index < b.index; });
        ASSERT_EQ(got.size(), want.size()) << "ray " << r;
        for (size_t i = 0; i < got.size(); ++i) {
            ASSERT_EQ(got[i].index, want[i].index) << "ray " << r;
            EXPECT_NEAR(got[i].t, want[i].t, 1e-6 * std::abs(want[i].t) + 1e-12);
            EXPECT_NEAR(got[i].distance2, want[i].distance2, 1e-6 * want[i].distance2 + 1e-15);
        }
        total += want.size();
    }
    EXPECT_GT(total, size_t(10 * kQueries));  // the rays do meet discs

    int visits = 0;  // an empty interval
    beams.query(glm::dvec3(0.5), glm::dvec3(1, 0, 0), 1, 0, [&](uint32_t, double, double) { ++visits; });
    EXPECT_EQ(visits, 0);
}

TEST(PhotonMap, DirectionPackingRoundTrip) {
    std::mt19937_64 rng(12);
    std::normal_distribution<double> g(0, 1);
    std::vector<glm::dvec3> directions;
    for (int a = 0; a < 3; ++a)
        for (double s : {-1.0, 1.0}) {
            glm::dvec3 axis(0);
            axis[a] = s;
            directions.push_back(axis);
        }
    while (directions.size() < 1000000) {
        glm::dvec3 v(g(rng), g(rng), g(rng));
        if (directions.size() % 10 == 0) v.z *= 1e-4;  // along the fold at the equator
        directions.push_back(glm::normalize(v));
    }
    double worst = 0;
    for (size_t i = 0; i < directions.size(); ++i) {
        const glm::dvec3 back(unpackDirection(packDirection(glm::vec3(directions[i]))));
        const double angle = std::atan2(glm::length(glm::cross(back, directions[i])), glm::dot(back, directions[i]));
        if (i < 6) {
            EXPECT_EQ(back, directions[i]);  // the axes are exact
        }
        worst = std::max(worst, angle);
    }
    EXPECT_LT(worst, 1e-4);
    std::printf("worst round-trip angle: %.3g rad\n", worst);
}

}  // namespace
}  // namespace tetglow
