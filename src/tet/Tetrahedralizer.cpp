#include "tet/Tetrahedralizer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>

#include <glm/common.hpp>

#include "base/Hash.h"
#include "tet/CacheDirectory.h"
#include "tet/FloodFill.h"
#include "tet/InteriorRepair.h"
#include "tet/MeshingMemory.h"
#include "tet/Predicates.h"
#include "tet/TetGenProcess.h"
#include "tet/VolumeBoundary.h"

namespace tetglow {

std::string TetOptions::switches() const {
    std::string s = "pYnQzA";
    const auto add = [&s](char option, double value) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%c%.17g", option, value);
        s += buf;
    };
    if (radiusEdgeRatio > 0) add('q', radiusEdgeRatio);
    if (maxVolume > 0) add('a', maxVolume);
    return s;
}

namespace {

// TetGen keeps the boundary exact (-Y) by never splitting it: a tet whose circumcentre, the
// point refinement would insert, lies too near a boundary face stays as it is, whatever -a
// asks (a box stays 12 tets at any max volume).
std::string maxVolumeWarning(const TetMesh& mesh, double maxVolume) {
    if (maxVolume <= 0) return "";
    size_t over = 0;
    double largest = 0;
    for (uint32_t t = 0; t < mesh.tets.size(); ++t) {
        const double v = mesh.tetVolume(t);
        over += v > maxVolume;
        largest = std::max(largest, v);
    }
    if (over == 0) return "";
    char text[320];
    std::snprintf(text, sizeof text,
                  "%zu of %zu tets are larger than the max volume %.6g (the largest %.6g): TetGen adds no point that "
                  "would split the exact boundary, and these tets' refinement points lie too near it",
                  over, mesh.tets.size(), maxVolume, largest);
    return text;
}

std::array<uint32_t, 3> sortedFace(const std::array<uint32_t, 4>& v, int j) {
    std::array<uint32_t, 3> f{v[kInwardFace[j][0]], v[kInwardFace[j][1]], v[kInwardFace[j][2]]};
    std::sort(f.begin(), f.end());
    return f;
}

// Surfaces that put one space in two regions: a scene to fix, not a failure of TetGen's.
struct InconsistentRegions : InputError {
    using InputError::InputError;
};

// The refusal of a space between the surfaces that two of their faces put in different regions:
// the mesh, both faces' positions and sides, and what makes that happen.
struct SideOfFace {
    uint32_t triangle;
    bool behind;
    int region;
};
std::string inconsistentRegions(const VolumeBoundary& boundary, const std::vector<std::string>& names,
                                const SideOfFace& a, const SideOfFace& b) {
    const auto mesh = [&](int surface) {
        if (size_t(surface) < names.size() && !names[size_t(surface)].empty()) return names[size_t(surface)];
        return names.size() == 1 ? std::string("the mesh") : "mesh " + std::to_string(surface);
    };
    const auto side = [&](const SideOfFace& f) {
        const TriangleMesh& m = boundary.surface;
        const glm::dvec3 centre = (m.corner(f.triangle, 0) + m.corner(f.triangle, 1) + m.corner(f.triangle, 2)) / 3.0;
        return (f.region < 0 ? std::string("outside every mesh") : "inside " + mesh(f.region)) +
               (f.behind ? " behind the face at " : " in front of the face at ") + formatPosition(centre) + " of " +
               mesh(int(boundary.source[f.triangle][0]));
    };
    const std::string name = names.size() == 1 ? names[0] : mesh(int(boundary.source[b.triangle][0]));
    return (name.empty() ? "" : name + ": ") +
           "the surfaces do not separate the regions consistently: one space between them is " + side(a) + " and " +
           side(b) + ", so one of these faces lies inside a solid or two surfaces meet without sharing faces";
}

// TetGen's vertices, the surface's first and unmoved (TetGen kept them all).
std::vector<glm::dvec3> tetVertices(const TriangleMesh& surface, const RawTets& raw) {
    const size_t nv = raw.points.size() / 3;
    std::vector<glm::dvec3> vertices(nv);
    for (size_t i = 0; i < nv; ++i) vertices[i] = {raw.points[3 * i], raw.points[3 * i + 1], raw.points[3 * i + 2]};
    for (size_t i = 0; i < surface.positions.size(); ++i)
        if (vertices[i] != surface.positions[i]) throw InputError("TetGen moved input vertex " + std::to_string(i));
    return vertices;
}

// TetGen's tets in its order, each with its neighbour across each face (-1 for none) and the
// surface triangle the face coincides with (-1 for none).
struct TetFaces {
    std::vector<std::array<uint32_t, 4>> tets;
    std::vector<std::array<int, 4>> nbr;
    std::vector<std::array<int64_t, 4>> onSurface;
};

// TetGen's tets and neighbours, every tet turned to positive orientation.
TetFaces orientedTets(const RawTets& raw, const std::vector<glm::dvec3>& vertices) {
    const size_t nv = vertices.size(), nt = raw.tets.size() / 4;
    TetFaces f;
    f.tets.resize(nt);
    f.nbr.resize(nt);
    for (size_t t = 0; t < nt; ++t)
        for (int j = 0; j < 4; ++j) {
            f.tets[t][j] = uint32_t(raw.tets[4 * t + j]);
            f.nbr[t][j] = raw.neighbours[4 * t + j];
            if (f.tets[t][j] >= nv || f.nbr[t][j] >= int(nt)) throw InputError("TetGen returned an index out of range");
        }
    for (size_t t = 0; t < nt; ++t) {
        const auto& v = f.tets[t];
        const double o = orient3d(vertices[v[0]], vertices[v[1]], vertices[v[2]], vertices[v[3]]);
        if (o == 0) throw InputError("TetGen produced a flat tetrahedron " + std::to_string(t));
        if (o > 0) {  // Shewchuk's orient3d is negative for our positive orientation
            std::swap(f.tets[t][0], f.tets[t][1]);
            std::swap(f.nbr[t][0], f.nbr[t][1]);
        }
    }
    return f;
}

// Per tet face: the surface triangle it coincides with, or -1.
void matchSurfaceFaces(TetFaces& f, const TriangleMesh& surface) {
    std::map<std::array<uint32_t, 3>, uint32_t> surfaceIndex;
    for (uint32_t s = 0; s < surface.triangles.size(); ++s) {
        auto tri = surface.triangles[s];
        std::sort(tri.begin(), tri.end());
        surfaceIndex.emplace(tri, s);
    }
    f.onSurface.resize(f.tets.size());
    for (size_t t = 0; t < f.tets.size(); ++t)
        for (int j = 0; j < 4; ++j) {
            auto it = surfaceIndex.find(sortedFace(f.tets[t], j));
            f.onSurface[t][j] = it == surfaceIndex.end() ? -1 : int64_t(it->second);
        }
}

// Tet face (t, j) on its surface triangle s lies behind s when the tet's other vertex does.
bool behind(const TetFaces& f, const TriangleMesh& surface, const std::vector<glm::dvec3>& vertices, size_t t, int j) {
    const auto& s = surface.triangles[size_t(f.onSurface[t][j])];
    return orient3d(vertices[s[0]], vertices[s[1]], vertices[s[2]], vertices[f.tets[t][j]]) > 0;
}

// The region of each tet, -1 outside every region: cells are flooded across faces that are not
// surface triangles, and each takes its region from the sides of the triangles that bound it.
std::vector<int> tetRegions(const VolumeBoundary& boundary, const std::vector<std::string>& names, const TetFaces& f,
                            const std::vector<glm::dvec3>& vertices) {
    constexpr int kUndecided = -2;
    std::vector<int> cellRegion;
    std::vector<SideOfFace> decidedBy;  // per cell: the face that gave it its region
    const std::vector<uint32_t> cell = floodFill(
        f.tets.size(),
        [&](uint32_t) {
            cellRegion.push_back(kUndecided);
            decidedBy.push_back({});
        },
        [&](uint32_t t, uint32_t id, const auto& reach) {
            for (int j = 0; j < 4; ++j) {
                if (f.onSurface[t][j] >= 0) {
                    const auto s = uint32_t(f.onSurface[t][j]);
                    const bool back = behind(f, boundary.surface, vertices, t, j);
                    const SideOfFace side{s, back, boundary.sides[s][back ? 0 : 1]};
                    if (cellRegion[id] == kUndecided) {
                        cellRegion[id] = side.region;
                        decidedBy[id] = side;
                    } else if (cellRegion[id] != side.region)
                        throw InconsistentRegions(inconsistentRegions(boundary, names, decidedBy[id], side));
                } else if (f.nbr[t][j] >= 0) {
                    reach(uint32_t(f.nbr[t][j]));
                }
            }
        });
    std::vector<int> region(f.tets.size());
    for (size_t t = 0; t < region.size(); ++t) region[t] = cellRegion[cell[t]] == kUndecided ? -1 : cellRegion[cell[t]];
    return region;
}

// With -A, TetGen's attribute of each kept tet must agree: the inside point's region + 1, or a
// number of TetGen's own (0 or above the regions') for a cell that no inside point reaches, such
// as a second shell of one mesh.
void checkAttributes(const std::vector<double>& attributes, const std::vector<int>& region, size_t regions) {
    std::vector<char> reached(regions, 0);
    for (size_t t = 0; t < region.size(); ++t) {
        const int r = region[t], a = int(std::lround(attributes[t]));
        if (r < 0) continue;
        if (a >= 1 && a <= int(regions) && a != r + 1)
            throw InputError("TetGen's region of tet " + std::to_string(t) + " disagrees with the surfaces");
        reached[r] |= a == r + 1;
    }
    for (size_t r = 0; r < regions; ++r)
        if (!reached[r])
            throw InputError("TetGen found no tets around the inside point of region " + std::to_string(r));
}

// The tets in a region, by region, each region's in Morton order of their centroids: a walk's
// next tet is then usually close in memory (TetGen's order is not spatial).
std::vector<uint32_t> mortonOrder(const std::vector<glm::dvec3>& vertices,
                                  const std::vector<std::array<uint32_t, 4>>& tets, const std::vector<int>& region) {
    Bounds3 box;
    for (const auto& v : vertices) box.extend(v);
    const glm::dvec3 scale = 1023.0 / glm::max(box.hi - box.lo, glm::dvec3(1e-300));
    auto spread = [](uint64_t x) {  // 10 bits -> every third of 30
        x = (x | (x << 16)) & 0x030000FF;
        x = (x | (x << 8)) & 0x0300F00F;
        x = (x | (x << 4)) & 0x030C30C3;
        return (x | (x << 2)) & 0x09249249;
    };
    std::vector<std::tuple<int, uint64_t, uint32_t>> order;
    for (uint32_t t = 0; t < tets.size(); ++t) {
        if (region[t] < 0) continue;
        const auto& v = tets[t];
        const glm::dvec3 c = (vertices[v[0]] + vertices[v[1]] + vertices[v[2]] + vertices[v[3]]) * 0.25;
        const glm::dvec3 q = glm::clamp((c - box.lo) * scale, 0.0, 1023.0);
        order.push_back(
            {region[t], spread(uint64_t(q.x)) | spread(uint64_t(q.y)) << 1 | spread(uint64_t(q.z)) << 2, t});
    }
    std::sort(order.begin(), order.end());
    std::vector<uint32_t> kept;
    kept.reserve(order.size());
    for (const auto& [r, code, t] : order) kept.push_back(t);
    return kept;
}

// The kept tets' adjacency, encoded, and the tet faces on each side of every surface triangle;
// `newIndex` maps TetGen's tets to the kept ones (-1 for one removed).
void linkFaces(TetMesh& m, const VolumeBoundary& boundary, const TetFaces& f, const std::vector<int64_t>& newIndex) {
    const TriangleMesh& surface = boundary.surface;
    m.adjacency.resize(m.tets.size());
    m.surfaceFace.assign(surface.triangles.size(), UINT32_MAX);
    m.surfaceFaceFront.assign(surface.triangles.size(), UINT32_MAX);
    for (size_t t = 0; t < f.tets.size(); ++t) {
        if (newIndex[t] < 0) continue;
        const auto nt_ = uint32_t(newIndex[t]);
        for (int j = 0; j < 4; ++j) {
            if (f.onSurface[t][j] >= 0) {
                const auto s = size_t(f.onSurface[t][j]);
                uint32_t& face = behind(f, surface, m.vertices, t, j) ? m.surfaceFace[s] : m.surfaceFaceFront[s];
                if (face != UINT32_MAX)
                    throw InputError("surface triangle " + std::to_string(s) + " bounds two tets on one side");
                face = 4 * nt_ + uint32_t(j);
                m.adjacency[nt_][j] = ~int32_t(s);
                continue;
            }
            const int n = f.nbr[t][j];
            if (n < 0 || newIndex[n] < 0)
                throw InputError("TetGen left an unmatched boundary face: the boundary was not preserved");
            int back = 0;
            while (back < 4 && f.nbr[n][back] != int(t)) ++back;
            if (back == 4) throw InputError("TetGen returned non-reciprocal neighbours");
            m.adjacency[nt_][j] = int32_t(4 * newIndex[n] + back);
        }
    }
    for (size_t s = 0; s < m.surfaceFace.size(); ++s)
        if (m.surfaceFace[s] == UINT32_MAX || (m.surfaceFaceFront[s] == UINT32_MAX) != (boundary.sides[s][1] < 0))
            throw InputError("surface triangle " + std::to_string(s) + " is not a tet face on each side with a region");
}

// Builds the TetMesh: positive orientation, encoded adjacency, boundary faces <-> surface
// triangles, tets grouped by region. TetGen fills every space the triangles enclose; the
// connected pieces between triangles (cells) take their region from the side of a triangle
// they lie on, exactly, and cells outside every region (such as the cavity of a hollow mesh)
// are removed.
TetMesh assemble(const VolumeBoundary& boundary, const RawTets& raw, const std::vector<std::string>& names) {
    const TriangleMesh& surface = boundary.surface;
    const size_t nt = raw.tets.size() / 4, nr = boundary.regionCount();
    if (nt == 0) throw InputError("TetGen produced no tetrahedra (is the mesh closed?)");
    if (raw.points.size() / 3 < surface.positions.size()) throw InputError("TetGen dropped input vertices");
    if (!raw.attributes.empty() && raw.attributes.size() != nt) throw InputError("TetGen lost the region attributes");
    TetMesh m;
    m.vertices = tetVertices(surface, raw);
    TetFaces faces = orientedTets(raw, m.vertices);
    matchSurfaceFaces(faces, surface);
    const std::vector<int> region = tetRegions(boundary, names, faces, m.vertices);
    if (!raw.attributes.empty()) checkAttributes(raw.attributes, region, nr);

    std::vector<int64_t> newIndex(nt, -1);
    m.regionTets.assign(nr + 1, 0);
    for (uint32_t t : mortonOrder(m.vertices, faces.tets, region)) {
        newIndex[t] = int64_t(m.tets.size());
        m.tets.push_back(faces.tets[t]);
        ++m.regionTets[size_t(region[t]) + 1];
    }
    for (size_t r = 0; r < nr; ++r) m.regionTets[r + 1] += m.regionTets[r];
    m.regionParent = boundary.parent;
    m.surface = surface.triangles;
    m.surfaceVertexCount = surface.positions.size();
    m.surfaceRegions = boundary.sides;
    m.surfaceSource = boundary.source;
    linkFaces(m, boundary, faces, newIndex);
    return m;
}

// The whole set of surfaces: TetGen's input (merged surface, inside points) and how it is read back
// (the sides of every triangle, the nesting).
uint64_t cacheKey(const VolumeBoundary& boundary, const std::string& switches) {
    const TriangleMesh& mesh = boundary.surface;
    uint64_t h = kFnvOffset;
    h = fnv1a(h, mesh.positions.data(), mesh.positions.size() * sizeof(mesh.positions[0]));
    h = fnv1a(h, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
    h = fnv1a(h, boundary.sides.data(), boundary.sides.size() * sizeof(boundary.sides[0]));
    h = fnv1a(h, boundary.source.data(), boundary.source.size() * sizeof(boundary.source[0]));
    h = fnv1a(h, boundary.parent.data(), boundary.parent.size() * sizeof(boundary.parent[0]));
    h = fnv1a(h, boundary.insidePoints.data(), boundary.insidePoints.size() * sizeof(boundary.insidePoints[0]));
    h = fnv1a(h, switches.data(), switches.size());
    return h;
}

// A failure of the meshes `names` with their names in front ("a.obj + b.obj: ..."), where it
// does not start with the first already (every refusal names the file it refuses).
std::string namedError(const std::vector<std::string>& names, const std::string& message) {
    std::string named;
    for (const std::string& n : names)
        if (!n.empty()) named += (named.empty() ? "" : " + ") + n;
    if (named.empty() || message.rfind(names[0], 0) == 0) return message;
    return named + ": " + message;
}

// Before validation allocates anything: the meshes, named, refused when tetrahedralizing them
// would not fit in memory.
void checkSurfacesMemory(const std::vector<TriangleMesh>& surfaces, const std::vector<std::string>& names) {
    size_t triangles = 0;
    for (const TriangleMesh& s : surfaces) triangles += s.triangles.size();
    try {
        checkMeshingMemory(triangles);
    } catch (const InputError& e) {
        throw InputError(namedError(names, e.what()));
    }
}

// The cache file of the tets keyed `key`, or none (and why not, in stats.cacheProblem).
std::filesystem::path cacheEntry(const TetOptions& options, uint64_t key, TetStats& stats) {
    if (!options.useCache) {
        stats.cacheProblem = "the cache is off";
        return {};
    }
    const auto dir = cacheDirectory(options.cacheDir);
    if (dir.empty()) {
        stats.cacheProblem = "no cache folder: none of TETGLOW_CACHE_DIR, XDG_CACHE_HOME and HOME is set";
        return {};
    }
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.tet", static_cast<unsigned long long>(key));
    return dir / name;
}

void fillCacheEntry(const TetMesh& mesh, uint64_t key, const std::filesystem::path& file, TetStats& stats) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    try {
        writeTetMesh(mesh, key, file.string(), false);
        stats.cacheFile = file.string();
    } catch (const std::exception& e) {
        // An unwritable cache only costs time on the next run.
        stats.cacheProblem = e.what();
    }
}

// The warning for the meshes whose boundary is approximate (the winding number's grid), each named.
std::string approximationWarning(const std::vector<ValidationReport>& validations,
                                 const std::vector<std::string>& names) {
    std::string warning;
    for (size_t i = 0; i < validations.size(); ++i) {
        const RepairReport& r = validations[i].repair;
        if (r.approximateReason.empty()) continue;
        const std::string text = r.summary() + (r.reason.empty() ? "" : " (the input: " + r.reason + ")");
        warning += (warning.empty() ? "" : "; ") + (names[i].empty() ? text : names[i] + ": " + text);
    }
    return warning;
}

}  // namespace

void checkTetCount(double volume, double maxVolume) {
    // Every tet is at most maxVolume, so there are at least volume / maxVolume of them.
    if (!(maxVolume > 0) || volume / maxVolume <= kMaxTets) return;
    char text[256];
    std::snprintf(
        text, sizeof text,
        "max volume %.6g (TetGen -a) would make at least %.3g tets of this mesh (volume %.6g), more than %.0f: "
        "use a max volume >= %.6g, or 0 for none",
        maxVolume, volume / maxVolume, volume, kMaxTets, volume / kMaxTets);
    throw InputError(text);
}

TetMesh tetrahedralizeUnchecked(const TriangleMesh& surface, const std::string& switches) {
    const VolumeBoundary boundary = singleRegion(surface);
    return assemble(boundary, runIsolated(boundary, switches), {""});
}

TetMesh tetrahedralize(std::vector<TriangleMesh> surfaces, const std::vector<std::string>& names,
                       const TetOptions& options, TetStats* stats, std::vector<ValidationReport>* reports) {
    const auto start = std::chrono::steady_clock::now();
    if (reports) reports->clear();
    checkSurfacesMemory(surfaces, names);
    // The meshes as given, for approximateSurface when TetGen fails on what validation made of them.
    const std::vector<TriangleMesh> inputs = options.strict ? std::vector<TriangleMesh>{} : surfaces;
    std::vector<ValidationReport> validations(surfaces.size());
    for (size_t i = 0; i < surfaces.size(); ++i) {
        try {
            validations[i] = prepareSurface(surfaces[i], options.strict, options.repairTimeLimit);
        } catch (const InputError& e) {
            throw InputError(names[i].empty() ? e.what() : names[i] + ": " + e.what());
        }
    }
    TetStats local;
    local.approximateWarning = approximationWarning(validations, names);
    double largestVolume = 0;  // the regions' union holds at least this much
    for (const ValidationReport& v : validations) largestVolume = std::max(largestVolume, v.volume);
    checkTetCount(largestVolume, options.maxVolume);
    VolumeBoundary boundary = buildVolumeBoundary(surfaces, names);
    placeInsidePoints(boundary, surfaces, names);
    const std::string switches = options.switches();
    const uint64_t key = cacheKey(boundary, switches);
    std::filesystem::path file = cacheEntry(options, key, local);
    TetMesh mesh;
    std::string problem;
    CacheRead cached = file.empty() ? CacheRead::Absent : readTetMesh(mesh, key, file.string(), &problem);
    const auto sameSurface = [&] {
        const auto& p = boundary.surface.positions;
        return mesh.surfaceVertexCount == p.size() && std::equal(p.begin(), p.end(), mesh.vertices.begin()) &&
               mesh.surface == boundary.surface.triangles && mesh.surfaceRegions == boundary.sides;
    };
    if (cached == CacheRead::Used && !sameSurface()) {  // a key collision
        cached = CacheRead::Damaged;
        problem = "it holds the tets of another set of meshes";
    }
    if (cached == CacheRead::Used) {
        local.fromCache = true;
        local.cacheFile = file.string();
    } else {
        if (cached == CacheRead::Damaged) {
            local.cacheWarning =
                file.string() + ": damaged tet cache entry (" + problem + "); not used, tetrahedralizing again";
            std::fprintf(stderr, "tetglow: warning: %s\n", local.cacheWarning.c_str());
        }
        try {
            mesh = assemble(boundary, runIsolated(boundary, switches), names);
        } catch (const InconsistentRegions&) {
            throw;
        } catch (const InputError& failure) {
            const std::string why = namedError(names, failure.what());
            // Every mesh not yet approximate is approximated: TetGen does not say which one it failed on.
            const auto exact = [](const ValidationReport& v) { return v.repair.approximateReason.empty(); };
            if (inputs.empty() || std::none_of(validations.begin(), validations.end(), exact)) throw InputError(why);
            try {
                for (size_t i = 0; i < inputs.size(); ++i) {
                    if (!exact(validations[i])) continue;
                    surfaces[i] = inputs[i];
                    const std::string validation = validations[i].repair.reason;
                    validations[i] = approximateSurface(
                        surfaces[i], "TetGen failed on the validated surface (" + oneLine(failure.what()) + ")");
                    validations[i].repair.reason = validation;
                }
                local.approximateWarning = approximationWarning(validations, names);
                boundary = buildVolumeBoundary(surfaces, names);
                placeInsidePoints(boundary, surfaces, names);
                mesh = assemble(boundary, runIsolated(boundary, switches), names);
            } catch (const InputError& e) {
                throw InputError(why + "; on the approximate boundary too: " + e.what());
            }
            file.clear();  // the entry is keyed by the surfaces TetGen failed on
            local.cacheProblem = "not cached: the boundary is approximate";
        }
        if (!file.empty()) fillCacheEntry(mesh, key, file, local);
    }
    if (reports) *reports = validations;
    if (!local.approximateWarning.empty())
        std::fprintf(stderr, "tetglow: warning: %s\n", local.approximateWarning.c_str());
    local.maxVolumeWarning = maxVolumeWarning(mesh, options.maxVolume);
    if (!local.maxVolumeWarning.empty()) std::fprintf(stderr, "tetglow: warning: %s\n", local.maxVolumeWarning.c_str());
    local.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = local;
    return mesh;
}

TetMesh tetrahedralize(TriangleMesh surface, const TetOptions& options, TetStats* stats, ValidationReport* report) {
    std::vector<ValidationReport> reports;
    TetMesh mesh = tetrahedralize({std::move(surface)}, {""}, options, stats, &reports);
    if (report) *report = reports.front();
    return mesh;
}

}  // namespace tetglow
