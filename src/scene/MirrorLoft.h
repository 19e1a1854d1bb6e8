// Closed shells lofted through mirror-symmetric cross-sections (the procedural fish's body and
// lure): the sections as overlapping superellipse lobes, their rings resampled to a target edge
// length, the rings stitched into triangles together with their mirror images.
//
// Why no resolution can self-intersect. Each shell is a loft through rings (cross-sections)
// ordered by falling x, mirror-symmetric about z = 0, and every cross-section meets each
// horizontal line in one interval. So the left half (z >= 0) of a ring runs from its top to
// its bottom with y strictly falling, and only its ends lie on the mirror plane. Rings are
// planar at falling x, so every triangle between two of them keeps its orientation when
// projected onto the x-y plane. In the caudal fin the rings are sheared into chevrons that stay
// ordered along x; the shear is linear above and below the equator and no triangle straddles
// it, so orientations survive that too. The left half is thus a height field z(x, y) and cannot
// cross itself; the right half is its mirror image, and the two meet only along the seams they
// share on the mirror plane.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "tet/TriangleMesh.h"

namespace tetglow::loft {

// A superellipse in the y-z plane centred on the mirror plane, with separate half-heights above
// and below its centre (a belly deeper than the back). Exponent 2 is an ellipse; fins use 4 for
// flatter sides.
struct Lobe {
    double centre, up, down, halfWidth, exponent = 2;

    double halfWidthAt(double y) const {
        const double u = y >= centre ? (y - centre) / up : (centre - y) / down;
        if (u >= 1) return 0;
        return exponent == 2 ? halfWidth * std::sqrt(1 - u * u)
                             : halfWidth * std::pow(1 - std::pow(u, exponent), 1 / exponent);
    }
};

// The points with |z| <= halfWidth(y) for overlapping lobes: one interval per horizontal line.
struct Section {
    std::vector<Lobe> lobes;

    // The half-width at height y, and which lobe gives it (-1 outside all of them).
    std::pair<double, int> halfWidth(double y) const {
        std::pair<double, int> widest{0, -1};
        for (size_t i = 0; i < lobes.size(); ++i)
            if (const double z = lobes[i].halfWidthAt(y); z > widest.first) widest = {z, static_cast<int>(i)};
        return widest;
    }
    double top() const {
        double y = -1e300;
        for (const auto& l : lobes) y = std::max(y, l.centre + l.up);
        return y;
    }
    double bottom() const {
        double y = 1e300;
        for (const auto& l : lobes) y = std::min(y, l.centre - l.down);
        return y;
    }
};

// The left half (z >= 0) of a ring from top to bottom, split at `equator` into an upper and a
// lower part. A pole is a single point; the tail's trailing edge lies wholly on the mirror plane.
// Neighbouring rings are stitched by pairing points that lie equally far along their parts,
// measured in pieces between features (`piece`: index + fraction, rising from the top) or,
// where the rings' features differ, in arc length (`fraction`: 0 at the top, 1 at the equator,
// 2 at the bottom).
struct Ring {
    std::vector<glm::dvec3> left;
    size_t equator = 0;
    std::vector<double> piece, fraction;
};

// Rounded to float, so that positions survive the OBJ's nine digits and validation's snap.
inline glm::dvec3 toFloat(const glm::dvec3& p) { return {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)}; }

// The length around the section, its left half split at `equator`.
double perimeter(const Section& section, double equator);
// The ring of `section` at x, its points about `edge` apart, split at `equator`.
Ring sampleRing(const Section& section, double x, double equator, double edge);
// A ring of the single point p, which closes a shell.
Ring pole(const glm::dvec3& p);
// Appends the closed shell lofted through `rings`, ordered by falling x; the first and last are
// poles or lie wholly on the mirror plane, which closes the shell there.
void appendLoft(TriangleMesh& mesh, const std::vector<Ring>& rings);

// Stations t in (0, 1] evenly spaced by arc length of a loft's profile (x, top, bottom, widest
// at t), with the lateral extents weighted down, so that round ends and fins' edges get the rings
// they need. `count` stations, the last at t = 1; or, for count 0, as many as keep them about
// `edge` apart.
template <class Profile>
std::vector<double> evenStations(const Profile& profile, int count, double edge = 0) {
    constexpr int kSamples = 4096;
    std::vector<double> arc(kSamples + 1, 0.0);
    glm::dvec4 previous{};
    for (int k = 0; k <= kSamples; ++k) {
        const glm::dvec4 q = profile(double(k) / kSamples);
        if (k > 0) {
            const glm::dvec4 d = q - previous;
            arc[k] = arc[k - 1] + std::sqrt(d.x * d.x + (d.y * d.y + d.z * d.z + d.w * d.w) / 3);
        }
        previous = q;
    }
    if (count == 0) count = std::max(4, static_cast<int>(std::lround(arc.back() / edge)));
    std::vector<double> stations;
    int k = 0;
    for (int i = 1; i <= count; ++i) {
        const double a = arc.back() * i / count;
        while (k < kSamples - 1 && arc[k + 1] < a) ++k;
        stations.push_back((k + (a - arc[k]) / (arc[k + 1] - arc[k])) / kSamples);
    }
    stations.back() = 1;
    return stations;
}

// A section's profile for evenStations: (x, top, bottom, widest), or the point `y` where it is empty.
glm::dvec4 profileOf(const Section& section, double x, double y);

}  // namespace tetglow::loft
