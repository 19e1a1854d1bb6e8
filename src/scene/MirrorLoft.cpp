#include "scene/MirrorLoft.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace tetglow::loft {
namespace {

// The boundary's left half as a fine polyline of (z, y), from the section's end at height `end`
// to the equator; the spacing shrinks towards `end`, where lobes close with a vertical tangent.
struct Trace {
    std::vector<glm::dvec2> points;
    std::vector<int> lobes;  // the lobe each point lies on
    std::vector<double> arc;

    Trace(const Section& section, double end, double equator) {
        constexpr int kSamples = 2048;
        for (int k = 0; k <= kSamples; ++k) {
            const double y = end + (equator - end) * (1 - std::cos(0.5 * std::numbers::pi * k / kSamples));
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

}  // namespace

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

namespace {

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

}  // namespace

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

glm::dvec4 profileOf(const Section& section, double x, double y) {
    if (section.lobes.empty()) return {x, y, y, 0};
    double widest = 0;
    for (const auto& l : section.lobes) widest = std::max(widest, l.halfWidth);
    return {x, section.top(), section.bottom(), widest};
}

}  // namespace tetglow::loft
