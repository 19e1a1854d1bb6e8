#include "tet/TetGenProcess.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include <fcntl.h>
#include <tetgen.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/ByteMessage.h"

namespace tetglow {
namespace {

std::string tetgenFailure(int code) {
    switch (code) {
        case 1: return "TetGen ran out of memory";
        case 2: return "TetGen hit an internal error on this mesh";
        case 3: return "TetGen found self-intersecting faces";
        case 4: return "TetGen found a feature too small to resolve (nearly touching faces)";
        case 5: return "TetGen found two facets too close to each other";
        case 10: return "TetGen rejected the input";
        default: return "TetGen failed (error " + std::to_string(code) + ")";
    }
}

// In the child: TetGen's tets as bytes; TetGen's thrown error codes become InputErrors.
std::string runTetGen(const VolumeBoundary& boundary, const std::string& switches) {
    const TriangleMesh& mesh = boundary.surface;
    int devnull = ::open("/dev/null", O_WRONLY);  // TetGen prints to stdout even when quiet
    if (devnull >= 0) ::dup2(devnull, STDOUT_FILENO);
    tetgenio in, out;
    in.firstnumber = 0;
    in.numberofpoints = int(mesh.positions.size());
    in.pointlist = new REAL[mesh.positions.size() * 3];
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = mesh.positions[i][k];
    in.numberoffacets = int(mesh.triangles.size());
    in.facetlist = new tetgenio::facet[mesh.triangles.size()];
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        tetgenio::facet& facet = in.facetlist[f];
        tetgenio::init(&facet);
        facet.numberofpolygons = 1;
        facet.polygonlist = new tetgenio::polygon[1];
        tetgenio::init(&facet.polygonlist[0]);
        facet.polygonlist[0].numberofvertices = 3;
        facet.polygonlist[0].vertexlist = new int[3];
        for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = int(mesh.triangles[f][k]);
    }
    in.numberofregions = int(boundary.insidePoints.size());
    in.regionlist = boundary.insidePoints.empty() ? nullptr : new REAL[5 * boundary.insidePoints.size()];
    for (size_t r = 0; r < boundary.insidePoints.size(); ++r) {
        for (int k = 0; k < 3; ++k) in.regionlist[5 * r + k] = boundary.insidePoints[r][k];
        in.regionlist[5 * r + 3] = double(r + 1);  // TetGen numbers the cells no inside point reaches itself
        in.regionlist[5 * r + 4] = -1;             // no volume bound of its own
    }
    tetgenbehavior b;
    std::vector<char> sw(switches.begin(), switches.end());
    sw.push_back('\0');
    if (!b.parse_commandline(sw.data())) throw std::logic_error("TetGen rejected the switches " + switches);
    try {
        tetrahedralize(&b, &in, &out);
    } catch (int code) {
        throw InputError(tetgenFailure(code));
    }
    ByteWriter m;
    const size_t tets = size_t(out.numberoftetrahedra);
    m.addItems(out.pointlist, 3 * size_t(out.numberofpoints));
    m.addItems(out.tetrahedronlist, 4 * tets);
    m.addItems(out.neighborlist, out.neighborlist ? 4 * tets : 0);
    const int na = out.numberoftetrahedronattributes;
    std::vector<double> attributes;
    for (size_t t = 0; na > 0 && t < tets; ++t) attributes.push_back(out.tetrahedronattributelist[t * na]);
    m.add(attributes);
    return std::move(m.bytes());
}

}  // namespace

bool hasCloseVertices(const std::vector<glm::dvec3>& points) {
    Bounds3 box;
    for (const glm::dvec3& p : points) box.extend(p);
    const double tolerance = 2e-8 * box.diagonal();
    if (!(tolerance > 0)) return false;
    // Cells of the tolerance's size: a close pair lies in one cell or two neighbouring ones.
    const auto cell = [&](const glm::dvec3& p) { return glm::i64vec3(glm::floor((p - box.lo) / tolerance)); };
    const auto key = [](const glm::i64vec3& c) {
        return uint64_t(c.x) * 0x9E3779B97F4A7C15ull ^ uint64_t(c.y) * 0xC2B2AE3D27D4EB4Full ^ uint64_t(c.z);
    };
    std::unordered_multimap<uint64_t, uint32_t> cells;
    for (uint32_t i = 0; i < points.size(); ++i) {
        const glm::i64vec3 c = cell(points[i]);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto [first, last] = cells.equal_range(key(c + glm::i64vec3(dx, dy, dz)));
                    for (auto it = first; it != last; ++it)
                        if (glm::distance(points[it->second], points[i]) < tolerance) return true;
                }
        cells.emplace(key(c), i);
    }
    return false;
}

RawTets runIsolated(const VolumeBoundary& boundary, const std::string& switches, double seconds) {
    // TetGen 1.5's Hilbert sort loops without end on an infinite or NaN point.
    for (const glm::dvec3& p : boundary.surface.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::logic_error("a point of TetGen's input is not finite");
    ChildLimits limits = meshingLimits(boundary.surface.triangles.size());
    if (seconds > 0) limits.seconds = std::min(limits.seconds, seconds);
    std::string answer;
    try {
        const std::string kept = hasCloseVertices(boundary.surface.positions) ? switches + "M0/1" : switches;
        answer = runInChild([&] { return runTetGen(boundary, kept); }, limits);
    } catch (const ChildFailure& e) {
        if (e.kind == ChildFailure::Kind::Signal)
            throw TetGenCrash("TetGen crashed (" + e.detail +
                              ") on this mesh; it likely has nearly touching or intersecting faces");
        throw InputError("TetGen " + std::string(e.what()));
    }
    ByteReader reply(std::move(answer), "TetGen");
    RawTets raw;
    raw.points = reply.items<double>();
    raw.tets = reply.items<int>();
    raw.neighbours = reply.items<int>();
    raw.attributes = reply.items<double>();
    return raw;
}

}  // namespace tetglow
