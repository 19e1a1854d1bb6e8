// The minimum cut that labels tets inside or outside where the winding number is uncertain
// (InsideLabels.h), on a field whose 1/2 level set is known exactly: a cube made of tet faces,
// inside a larger box, with noise added where the labels are uncertain.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "tet/InsideLabels.h"

namespace tetglow {
namespace {

// The unit box cut into n^3 cubes of six tets each (Kuhn's triangulation: every tet runs from a
// cube's lowest corner to its highest along the axes in one order, so neighbouring cubes share
// faces); the cube [1/4, 3/4]^3 is then made of tet faces. Neighbours across every face but the box's.
struct NestedCubes {
    static constexpr int n = 16;
    std::vector<glm::dvec3> points;
    std::vector<std::array<uint32_t, 4>> tets;
    std::vector<std::array<int, 4>> neighbours;
    NestedCubes() {
        const auto index = [](int i, int j, int k) { return uint32_t((i * (n + 1) + j) * (n + 1) + k); };
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                for (int k = 0; k <= n; ++k) points.push_back(glm::dvec3(i, j, k) / double(n));
        std::array<int, 3> axes{0, 1, 2};
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    std::sort(axes.begin(), axes.end());
                    do {
                        glm::ivec3 corner(i, j, k);
                        std::array<uint32_t, 4> tet;
                        tet[0] = index(i, j, k);
                        for (int step = 0; step < 3; ++step) {
                            corner[axes[step]] += 1;
                            tet[step + 1] = index(corner.x, corner.y, corner.z);
                        }
                        tets.push_back(tet);
                    } while (std::next_permutation(axes.begin(), axes.end()));
                }
        std::map<std::array<uint32_t, 3>, std::pair<int, int>> faces;  // sorted face -> its tet, the other
        for (int t = 0; t < int(tets.size()); ++t)
            for (int j = 0; j < 4; ++j) {
                auto f = faceOf(tets[size_t(t)], j);
                std::sort(f.begin(), f.end());
                auto [it, added] = faces.emplace(f, std::pair(t, -1));
                if (!added) it->second.second = t;
            }
        neighbours.resize(tets.size());
        for (size_t t = 0; t < tets.size(); ++t)
            for (int j = 0; j < 4; ++j) {
                auto f = faceOf(tets[t], j);
                std::sort(f.begin(), f.end());
                const auto [a, b] = faces.at(f);
                neighbours[t][j] = a == int(t) ? b : a;
            }
    }
    glm::dvec3 centroid(size_t t) const {
        return 0.25 * (points[tets[t][0]] + points[tets[t][1]] + points[tets[t][2]] + points[tets[t][3]]);
    }
    // The winding number a cube of half-width 1/4 would have if it were blurred over 0.1 (1/2 on
    // its faces), plus `noise` times a fixed pseudo-random number in [-1, 1] per tet.
    std::vector<double> winding(double noise) const {
        std::vector<double> w(tets.size());
        for (uint32_t t = 0; t < w.size(); ++t) {
            const glm::dvec3 c = centroid(t);
            double depth = INFINITY;  // from the cube's surface, positive inside
            for (int k = 0; k < 3; ++k) depth = std::min(depth, 0.25 - std::abs(c[k] - 0.5));
            const double random = std::fmod(std::abs(std::sin(t * 12.9898) * 43758.5453), 1.0) * 2 - 1;
            w[t] = 0.5 + 0.5 * std::clamp(depth / 0.1, -1.0, 1.0) + noise * random;
        }
        return w;
    }
    std::vector<char> labels(const std::vector<double>& w, double gammaPerEdge) const {
        return insideLabels(points, tets, neighbours, w, {}, gammaPerEdge);
    }
    // The volume labelled inside and the area of the faces between inside and outside.
    std::pair<double, double> volumeAndArea(const std::vector<char>& inside) const {
        double volume = 0, area = 0;
        for (uint32_t t = 0; t < inside.size(); ++t) {
            if (!inside[t]) continue;
            const auto& v = tets[t];
            volume += std::abs(glm::dot(points[v[1]] - points[v[0]],
                                        glm::cross(points[v[2]] - points[v[0]], points[v[3]] - points[v[0]]))) /
                      6;
            for (int j = 0; j < 4; ++j) {
                if (neighbours[t][j] >= 0 && inside[size_t(neighbours[t][j])]) continue;
                const auto f = faceOf(tets[t], j);
                area += 0.5 * glm::length(glm::cross(points[f[1]] - points[f[0]], points[f[2]] - points[f[0]]));
            }
        }
        return {volume, area};
    }
};

// The threshold's labels are jagged where noise moves the winding number across 1/2; the cut
// gives the cube back: its area 3/2 and volume 1/8, each within 1%.
TEST(InsideLabels, NoisyWindingNumbersGiveTheCube) {
    const NestedCubes cubes;
    const std::vector<double> w = cubes.winding(0.1);
    const auto [thresholdVolume, thresholdArea] = cubes.volumeAndArea(cubes.labels(w, 0));
    const auto [volume, area] = cubes.volumeAndArea(cubes.labels(w, kCutGammaPerEdge));
    std::printf("cube: area 1.5, volume 0.125; threshold: area %.6f, volume %.6f; cut: area %.6f, volume %.6f\n",
                thresholdArea, thresholdVolume, area, volume);
    EXPECT_GT(thresholdArea, 1.3 * 1.5);  // the case is one where the threshold fails
    EXPECT_NEAR(area, 1.5, 0.01 * 1.5);
    EXPECT_NEAR(volume, 0.125, 0.01 * 0.125);
}

// Without noise every tet is on the side of 1/2 the cube puts it, and the cut keeps those labels
// (a gamma large enough to round the cube's edges would not); with winding numbers of only 0 and
// 1, as a clean closed part has, no tet is uncertain and the labels are the threshold's.
TEST(InsideLabels, CertainLabelsAreTheThreshold) {
    const NestedCubes cubes;
    std::vector<double> w = cubes.winding(0);
    std::vector<char> threshold(w.size());
    for (size_t t = 0; t < w.size(); ++t) threshold[t] = w[t] > 0.5;
    const std::vector<char> cut = cubes.labels(w, kCutGammaPerEdge);
    EXPECT_EQ(cut, threshold);
    const auto [volume, area] = cubes.volumeAndArea(cut);
    EXPECT_NEAR(volume, 0.125, 1e-12);
    EXPECT_NEAR(area, 1.5, 1e-12);
    for (double& x : w) x = x > 0.5 ? 1 : 0;
    EXPECT_EQ(cubes.labels(w, kCutGammaPerEdge), threshold);
}

TEST(InsideLabels, SameLabelsTwice) {
    const NestedCubes cubes;
    const std::vector<double> w = cubes.winding(0.2);
    const std::vector<char> first = cubes.labels(w, kCutGammaPerEdge);
    EXPECT_EQ(NestedCubes().labels(w, kCutGammaPerEdge), first);
    EXPECT_NE(std::count(first.begin(), first.end(), 1), 0);
}

}  // namespace
}  // namespace tetglow
