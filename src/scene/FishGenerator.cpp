#include "scene/FishGenerator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "scene/MirrorLoft.h"
#include "tet/Nesting.h"
#include "tet/Shapes.h"

namespace tetglow {
using namespace loft;
namespace {

constexpr double kPi = std::numbers::pi;

// The fish runs along s in [0, 1] from the nose to the notch of the tail fork.
constexpr double kNoseX = 0.9, kNotchX = -0.8;
constexpr double kCaudalStart = 0.72;  // s where the caudal fin begins to flare

double fishX(double s) { return kNoseX + (kNotchX - kNoseX) * s; }

// Quarter ellipse rising from 0 at the nose to 1 at s = r: the rounded head.
double rounded(double s, double r) {
    const double u = std::min(s / r, 1.0);
    return std::sqrt(u * (2 - u));
}

// Height of a fin along its base, u in [0, 1]: u^a (1 - u)^b scaled to peak at 1 (at u = a / (a + b)).
// Exponents of at least 1 keep the edges from rising vertically, which would pack rings there.
double finProfile(double u, double a, double b) {
    if (u <= 0 || u >= 1) return 0;
    const double peak = a / (a + b);
    return std::pow(u / peak, a) * std::pow((1 - u) / (1 - peak), b);
}

double caudalHeight(double s) { return 0.035 + 0.345 * std::pow((s - kCaudalStart) / (1 - kCaudalStart), 1.25); }

Section fishSection(double s, const FishParams& p) {
    Section section;
    // Body: a big round head and deep jaw tapering to a slender peduncle that ends in the tail.
    const double taper = (s < 0.3 ? 1 : 0.15 + 0.85 * (0.5 + 0.5 * std::cos(kPi * std::min((s - 0.3) / 0.52, 1.0)))) *
                         (s < 0.8 ? 1 : 1 - std::pow(std::min((s - 0.8) / 0.13, 1.0), 2));
    const double back = 0.27 * rounded(s, 0.26) * taper, belly = 0.31 * rounded(s, 0.16) * taper;
    const double side = 0.22 * rounded(s, 0.2) * taper;
    if (taper > 1e-3) section.lobes.push_back({0, back, belly, side});

    const double fin = p.finThickness / 2;
    if (const double h = 0.17 * finProfile((s - 0.42) / 0.28, 1, 1.6); h > 1e-3)  // dorsal
        section.lobes.push_back({back, h, h, fin, 4});
    if (const double h = 0.12 * finProfile((s - 0.58) / 0.18, 1, 1.4); h > 1e-3)  // anal
        section.lobes.push_back({-belly, h, h, fin, 4});
    if (const double span = 0.2 * finProfile((s - 0.27) / 0.16, 2, 1); span > 1e-3) {  // pectorals, one lobe for both
        // At 0.3 of the belly depth below the equator the body is sqrt(1 - 0.3^2) of its widest.
        section.lobes.push_back({-0.3 * belly, fin, fin, side * std::sqrt(1 - 0.09) + span});
    }
    if (s > kCaudalStart) {
        const double u = (s - kCaudalStart) / (1 - kCaudalStart);
        section.lobes.push_back({0, caudalHeight(s), caudalHeight(s), fin * (1.4 - 0.5 * u), 4});
    }
    return section;
}

// Shear that bends the caudal fin's rings into chevrons, x -= fork(s) * |y|, so that the lobes
// sweep back into a forked tail. It grows along s, which keeps the rings ordered along x.
double fork(double s, const FishParams& p) {
    if (s <= kCaudalStart) return 0;
    const double u = (s - kCaudalStart) / (1 - kCaudalStart);
    return p.tailFork / caudalHeight(1) * u * u;
}

std::vector<double> ringStations(const FishParams& p) {
    return evenStations([&](double s) { return profileOf(fishSection(s, p), fishX(s), 0); }, p.rings);
}

// The lure: a bulb hanging ahead of and above the nose on a stalk (the illicium) that rises
// steeply from the top of the head and arches forward into the back of the bulb, one shell lofted
// along x like the body. The stalk's base is a slender point just clear of the head, so that the
// two shells never meet. Each ring of the stalk is its tilted round cross-section cut by the plane
// x = const, an ellipse centred on the mirror plane, so the loft's argument above holds for it
// too; the stalk ends level, at the bulb's centre height, so that near the bulb every ring's
// stalk and bulb overlap (a ring of two separate lobes would pinch the shell).
constexpr double kStalkBaseS = 0.12;                             // where on the head the stalk rises
constexpr double kStalkClearance = 0.006;                        // between the stalk's base and the head
constexpr double kStalkRise = 2;                                 // the stalk's slope dy/dx at its base
constexpr double kStalkRadius = 0.011, kStalkTipRadius = 0.007;  // at its base and where it enters the bulb

// The lure bulb's centre: just ahead of and above the nose.
glm::dvec3 lureCentre(const FishParams& p) { return {kNoseX + 0.06 + p.lureRadius, 0.3, 0}; }

struct Stalk {
    glm::dvec2 base, end;  // (x, y) of the base's point and of the stalk's end, inside the bulb

    explicit Stalk(const FishParams& p)
        : base(fishX(kStalkBaseS), fishSection(kStalkBaseS, p).top() + kStalkClearance),
          end(lureCentre(p).x - 0.5 * p.lureRadius, lureCentre(p).y) {}

    double length() const { return end.x - base.x; }
    double u(double x) const { return std::clamp((x - base.x) / length(), 0.0, 1.0); }
    // The centre line: a cubic Hermite curve, slope kStalkRise at the base and level at the end.
    double centre(double x) const {
        const double t = u(x);
        return base.y + (end.y - base.y) * t * t * (3 - 2 * t) + kStalkRise * length() * t * (1 - t) * (1 - t);
    }
    double slope(double x) const {
        const double t = u(x);
        return (end.y - base.y) * 6 * t * (1 - t) / length() + kStalkRise * (1 - t) * (1 - 3 * t);
    }
    // Tapering from base to tip, with a pointed end over the first three base radii.
    double radius(double x) const {
        return glm::mix(kStalkRadius, kStalkTipRadius, u(x)) * rounded(x - base.x, 3 * kStalkRadius);
    }
};

Section lureSection(double x, const Stalk& stalk, const FishParams& p) {
    Section section;
    const double r = p.lureRadius, dx = x - lureCentre(p).x;
    if (std::abs(dx) < r) {
        const double h = std::sqrt(r * r - dx * dx);
        section.lobes.push_back({lureCentre(p).y, h, h, h});
    }
    if (x > stalk.base.x && x < stalk.end.x) {
        const double w = stalk.radius(x), h = w * std::sqrt(1 + stalk.slope(x) * stalk.slope(x));
        section.lobes.push_back({stalk.centre(x), h, h, w});
    }
    return section;
}

void appendLure(TriangleMesh& mesh, const FishParams& p, double edge) {
    const Stalk stalk(p);
    const glm::dvec3 centre = lureCentre(p);
    const double front = centre.x + p.lureRadius;
    auto xAt = [&](double t) { return glm::mix(front, stalk.base.x, t); };
    // The rings split into upper and lower parts at the stalk's centre line, level with the
    // bulb's centre where the two meet.
    auto equator = [&](double x) { return stalk.centre(x); };
    const std::vector<double> stations = evenStations(
        [&](double t) { return profileOf(lureSection(xAt(t), stalk, p), xAt(t), equator(xAt(t))); }, 0, edge);

    std::vector<Ring> lure{pole({front, centre.y, 0})};
    for (size_t i = 0; i + 1 < stations.size(); ++i) {
        const double x = xAt(stations[i]);
        lure.push_back(sampleRing(lureSection(x, stalk, p), x, equator(x), edge));
    }
    lure.push_back(pole({stalk.base.x, stalk.base.y, 0}));
    appendLoft(mesh, lure);
}

void check(bool ok, const std::string& what) {
    if (!ok) throw InputError("fish: " + what);
}

}  // namespace

TriangleMesh makeFish(const FishParams& p) {
    check(p.rings >= 8 && p.rings <= 2048, "rings must be 8 to 2048, got " + std::to_string(p.rings));
    check(p.segments >= 8 && p.segments <= 2048, "segments must be 8 to 2048, got " + std::to_string(p.segments));
    // Far apart, they make needle triangles that TetGen struggles to recover.
    check(p.rings <= 4 * p.segments && p.segments <= 4 * p.rings,
          "rings and segments must be within a factor of 4 of each other, got " + std::to_string(p.rings) + " and " +
              std::to_string(p.segments));
    check(p.finThickness >= 0.02 && p.finThickness <= 0.08, "fin thickness must be 0.02 to 0.08");
    check(p.tailFork >= 0 && p.tailFork <= 0.3, "tail fork must be 0 to 0.3");
    check(p.lureRadius == 0 || (p.lureRadius >= 0.02 && p.lureRadius <= 0.1), "lure radius must be 0 or 0.02 to 0.1");

    const std::vector<double> stations = ringStations(p);
    std::vector<Section> sections;
    double longest = 0;
    for (double s : stations) {
        sections.push_back(fishSection(s, p));
        if (s < 1) longest = std::max(longest, perimeter(sections.back(), 0));
    }
    const double edge = longest / p.segments;

    std::vector<Ring> body{pole({kNoseX, 0, 0})};
    for (size_t i = 0; i < stations.size(); ++i) {
        const double s = stations[i];
        Ring ring;
        if (s < 1) {
            ring = sampleRing(sections[i], fishX(s), 0, edge);
        } else {
            // The trailing edge: the caudal fin closes to zero thickness on the mirror plane.
            const int n = std::max(1, static_cast<int>(std::lround(caudalHeight(1) / edge)));
            for (int k = -n; k <= n; ++k) {
                ring.left.push_back(toFloat({fishX(1), -caudalHeight(1) * k / n, 0}));
                ring.piece.push_back(double(k + n) / n);
            }
            ring.fraction = ring.piece;
            ring.equator = n;
        }
        for (auto& q : ring.left) q.x = roundToFloat(q.x - fork(s, p) * std::abs(q.y));
        body.push_back(ring);
    }

    TriangleMesh mesh;
    appendLoft(mesh, body);

    // Finer than the body's triangles: the stalk's rings get about eight edges around.
    if (p.lureRadius > 0) appendLure(mesh, p, edge / 2);
    return mesh;
}

namespace {

// A point inside the body's own lobe (the first) at station s: `up` in [-1, 1] of its depth
// above (or, negative, below) the centre line, `side` in (-1, 1) of its half-width there.
glm::dvec3 insideBody(double s, double up, double side, const FishParams& p) {
    const Lobe body = fishSection(s, p).lobes.front();
    const double y = body.centre + up * (up >= 0 ? body.up : body.down);
    return {fishX(s), y, side * body.halfWidthAt(y)};
}

// Organs as icospheres, every vertex checked against `container` exactly (classifyPoint).
TriangleMesh organs(const std::vector<glm::dvec3>& centres, double radius, int subdivisions,
                    const TriangleMesh& container, const FishParams& p, const char* what) {
    TriangleMesh mesh;
    for (const auto& c : centres) {
        const TriangleMesh sphere = icosphere(subdivisions, radius, c);
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (const auto& v : sphere.positions) {
            const glm::dvec3 q = toFloat(v);
            check(classifyPoint(container, q) == PointSide::Inside,
                  std::string(what) + " do not fit inside the fish at " + std::to_string(p.rings) + " rings and " +
                      std::to_string(p.segments) + " segments: use more of either");
            mesh.positions.push_back(q);
        }
        for (const auto& t : sphere.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return mesh;
}

}  // namespace

TriangleMesh makeFishPhotophores(const FishParams& p) {
    // Two rows along the lower flanks from behind the head to the anal fin, as in lanternfish.
    std::vector<glm::dvec3> centres;
    for (int i = 0; i < 7; ++i)
        for (const double side : {0.55, -0.55}) centres.push_back(insideBody(0.2 + 0.05 * i, -0.62, side, p));
    return organs(centres, 0.022, 1, makeFish(p), p, "photophores");
}

TriangleMesh makeFishEyes(const FishParams& p) {
    return organs({insideBody(0.1, 0.3, 0.55, p), insideBody(0.1, 0.3, -0.55, p)}, 0.045, 2, makeFish(p), p, "eyes");
}

TriangleMesh makeFishLureCore(const FishParams& p) {
    check(p.lureRadius > 0, "the lure core needs a lure (lure radius > 0)");
    return organs({lureCentre(p)}, 0.45 * p.lureRadius, 2, makeFish(p), p, "the lure core");
}

}  // namespace tetglow
