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

#include "tet/Nesting.h"
#include "tet/Shapes.h"

namespace tetglow {
namespace {

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

constexpr double kPi = std::numbers::pi;

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
glm::dvec3 toFloat(const glm::dvec3& p) { return {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)}; }

// The boundary's left half as a fine polyline of (z, y), from the section's end at height `end`
// to the equator; the spacing shrinks towards `end`, where lobes close with a vertical tangent.
struct Trace {
    std::vector<glm::dvec2> points;
    std::vector<int> lobes;  // the lobe each point lies on
    std::vector<double> arc;

    Trace(const Section& section, double end, double equator) {
        constexpr int kSamples = 2048;
        for (int k = 0; k <= kSamples; ++k) {
            const double y = end + (equator - end) * (1 - std::cos(0.5 * kPi * k / kSamples));
            const auto [z, lobe] = section.halfWidth(y);
            points.push_back({k == 0 ? 0.0 : z, y});
            lobes.push_back(lobe);
            arc.push_back(k == 0 ? 0.0 : arc.back() + glm::distance(points[k - 1], points[k]));
        }
    }
    double length() const { return arc.back(); }
};

// A part of a ring's left half resampled from its end on the mirror plane to the equator.
struct PartSamples {
    std::vector<glm::dvec2> points;  // (z, y)
    std::vector<double> piece;       // index of the piece between features + fraction along it
    std::vector<double> fraction;    // fraction of the part's arc length
};

// Resamples a trace about `edge` apart by arc length. Fin tips (local maxima of the half-width)
// and the creases where one lobe meets another are kept as vertices, so that fins keep their
// span and their roots run straight along the body at every resolution.
PartSamples resample(const Trace& trace, double edge) {
    const auto& p = trace.points;
    const auto& arc = trace.arc;
    const size_t last = p.size() - 1;
    std::vector<size_t> breaks{0};
    for (size_t k = 1; k < last; ++k) {
        const bool tip = p[k].x > p[k - 1].x && p[k].x >= p[k + 1].x;
        const bool crease = trace.lobes[k] != trace.lobes[k - 1];
        if ((tip || crease) && arc[k] - arc[breaks.back()] > edge / 2 && arc[last] - arc[k] > edge / 2)
            breaks.push_back(k);
    }
    breaks.push_back(last);

    PartSamples out{{p[0]}, {0.0}, {0.0}};
    size_t k = 0;
    for (size_t b = 0; b + 1 < breaks.size(); ++b) {
        const double a0 = arc[breaks[b]], a1 = arc[breaks[b + 1]];
        const int n = std::max(1, static_cast<int>(std::lround((a1 - a0) / edge)));
        for (int i = 1; i <= n; ++i) {
            const double a = a0 + (a1 - a0) * i / n;
            if (i < n) {
                while (arc[k + 1] < a) ++k;
                out.points.push_back(glm::mix(p[k], p[k + 1], (a - arc[k]) / (arc[k + 1] - arc[k])));
            } else {
                out.points.push_back(p[breaks[b + 1]]);
            }
            out.piece.push_back(b + double(i) / n);
            out.fraction.push_back(a / arc[last]);
        }
    }
    return out;
}

double perimeter(const Section& section, double equator) {
    return 2 * (Trace(section, section.top(), equator).length() + Trace(section, section.bottom(), equator).length());
}

Ring sampleRing(const Section& section, double x, double equator, double edge) {
    const PartSamples upper = resample(Trace(section, section.top(), equator), edge);
    const PartSamples lower = resample(Trace(section, section.bottom(), equator), edge);
    Ring ring;
    for (size_t k = 0; k < upper.points.size(); ++k) {
        ring.left.push_back(toFloat({x, upper.points[k].y, upper.points[k].x}));
        ring.piece.push_back(upper.piece[k]);
        ring.fraction.push_back(upper.fraction[k]);
    }
    ring.equator = ring.left.size() - 1;
    // The lower part was sampled from the bottom up.
    const double pieces = ring.piece.back() + lower.piece.back();
    for (size_t k = lower.points.size() - 1; k-- > 0;) {
        ring.left.push_back(toFloat({x, lower.points[k].y, lower.points[k].x}));
        ring.piece.push_back(pieces - lower.piece[k]);
        ring.fraction.push_back(2 - lower.fraction[k]);
    }
    return ring;
}

Ring pole(const glm::dvec3& p) { return Ring{{toFloat(p)}, 0, {0.0}, {0.0}}; }

bool onMirror(const glm::dvec3& p) { return p.z == 0; }

// One part (upper or lower) of a ring's left half, with the ids of its vertices and of their
// mirror images.
struct Part {
    const Ring& ring;
    const std::vector<uint32_t>& ids;
    const std::vector<uint32_t>& mirrorIds;
    size_t first, last;

    const glm::dvec3& operator[](size_t i) const { return ring.left[i]; }
    double pieces() const { return ring.piece[last] - ring.piece[first]; }
    bool allOnMirror() const {
        for (size_t i = first; i <= last; ++i)
            if (!onMirror(ring.left[i])) return false;
        return true;
    }
};

// Tiles the strip between part a and part b (b further along -x), merging their points in order
// of how far along their parts they lie (in pieces between features where both parts have the
// same features, else in arc length), and emits every triangle together with its mirror image.
// A triangle with all corners on the mirror plane would coincide with its own mirror image, so
// steps that make one, or that leave only such triangles to finish, are not taken.
void tileStrip(TriangleMesh& mesh, const Part& a, const Part& b) {
    const bool aSeam = a.allOnMirror(), bSeam = b.allOnMirror();
    const bool byPiece = a.pieces() == b.pieces();
    auto along = [&](const Part& part, size_t i) {
        return byPiece ? part.ring.piece[i] - part.ring.piece[part.first] : part.ring.fraction[i];
    };
    auto emit = [&](const Part& p, size_t i, const Part& q, size_t j, const Part& r, size_t k) {
        mesh.triangles.push_back({p.ids[i], q.ids[j], r.ids[k]});
        mesh.triangles.push_back({r.mirrorIds[k], q.mirrorIds[j], p.mirrorIds[i]});
    };
    auto flat = [](const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
        return onMirror(p) && onMirror(q) && onMirror(r);
    };
    size_t i = a.first, j = b.first;
    while (i < a.last || j < b.last) {
        const bool advanceA = i < a.last && !flat(a[i], a[i + 1], b[j]) &&
                              !(i + 1 == a.last && onMirror(a[i + 1]) && bSeam && j < b.last);
        const bool advanceB = j < b.last && !flat(a[i], b[j], b[j + 1]) &&
                              !(j + 1 == b.last && onMirror(b[j + 1]) && aSeam && i < a.last);
        if (!advanceA && !advanceB) throw std::logic_error("fish loft: strip cannot be tiled");
        if (advanceA && (!advanceB || along(a, i + 1) <= along(b, j + 1))) {
            emit(a, i, b, j, a, i + 1);
            ++i;
        } else {
            emit(a, i, b, j, b, j + 1);
            ++j;
        }
    }
}

// Appends the closed shell lofted through `rings`, ordered by falling x; the first and last are
// poles or lie wholly on the mirror plane, which closes the shell there.
void appendLoft(TriangleMesh& mesh, const std::vector<Ring>& rings) {
    std::vector<std::vector<uint32_t>> ids(rings.size()), mirrorIds(rings.size());
    for (size_t r = 0; r < rings.size(); ++r)
        for (const auto& p : rings[r].left) {
            ids[r].push_back(static_cast<uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(p);
            if (onMirror(p)) {
                mirrorIds[r].push_back(ids[r].back());
            } else {
                mirrorIds[r].push_back(static_cast<uint32_t>(mesh.positions.size()));
                mesh.positions.push_back({p.x, p.y, -p.z});
            }
        }
    for (size_t r = 0; r + 1 < rings.size(); ++r) {
        const Ring &a = rings[r], &b = rings[r + 1];
        tileStrip(mesh, {a, ids[r], mirrorIds[r], 0, a.equator}, {b, ids[r + 1], mirrorIds[r + 1], 0, b.equator});
        tileStrip(mesh, {a, ids[r], mirrorIds[r], a.equator, a.left.size() - 1},
                  {b, ids[r + 1], mirrorIds[r + 1], b.equator, b.left.size() - 1});
    }
}

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
glm::dvec4 profileOf(const Section& section, double x, double y) {
    if (section.lobes.empty()) return {x, y, y, 0};
    double widest = 0;
    for (const auto& l : section.lobes) widest = std::max(widest, l.halfWidth);
    return {x, section.top(), section.bottom(), widest};
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
