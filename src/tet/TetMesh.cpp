#include "tet/TetMesh.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include <glm/geometric.hpp>

#include "base/Hash.h"
#include "base/InputFile.h"
#include "base/OutputFile.h"
#include "tet/Predicates.h"

namespace tetglow {

double TetMesh::tetVolume(uint32_t t) const {
    const auto& v = tets[t];
    const glm::dvec3 a = vertices[v[0]];
    return glm::dot(vertices[v[1]] - a, glm::cross(vertices[v[2]] - a, vertices[v[3]] - a)) / 6.0;
}

double TetMesh::volume() const {
    double sum = 0;
    for (uint32_t t = 0; t < tets.size(); ++t) sum += tetVolume(t);
    return sum;
}

int32_t TetMesh::regionOf(uint32_t t) const {
    return int32_t(std::upper_bound(regionTets.begin() + 1, regionTets.end() - 1, t) - regionTets.begin()) - 1;
}

double TetMesh::regionVolume(int32_t r) const {
    double sum = 0;
    for (uint32_t t = regionTets[r]; t < regionTets[r + 1]; ++t) sum += tetVolume(t);
    return sum;
}

double TetMesh::regionSurfaceVolume(int32_t r) const {
    double sum = 0;
    for (size_t s = 0; s < surface.size(); ++s) {
        const int sign = (surfaceRegions[s][0] == r) - (surfaceRegions[s][1] == r);
        if (sign == 0) continue;
        const glm::dvec3 a = vertices[surface[s][0]], b = vertices[surface[s][1]], c = vertices[surface[s][2]];
        sum += sign * glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return sum;
}

double TetMesh::surfaceVolume() const { return signedVolume(surfaceMesh()); }

glm::dvec3 TetMesh::centroid(uint32_t t) const {
    const auto& v = tets[t];
    return (vertices[v[0]] + vertices[v[1]] + vertices[v[2]] + vertices[v[3]]) * 0.25;
}

TriangleMesh TetMesh::surfaceMesh() const {
    TriangleMesh m;
    m.positions.assign(vertices.begin(), vertices.begin() + surfaceVertexCount);
    m.triangles = surface;
    return m;
}

uint32_t TetMesh::surfaceAcross(uint32_t s, uint32_t a, uint32_t b) const {
    uint32_t tet = surfaceFace[s] >> 2;
    uint32_t apex = tets[tet][surfaceFace[s] & 3];  // opposite the face we stand on
    for (size_t guard = 0; guard <= tets.size(); ++guard) {
        // The other face through (a, b) is opposite the vertex that is neither a, b nor the apex.
        const auto& v = tets[tet];
        int j = 0;
        while (v[j] == a || v[j] == b || v[j] == apex) ++j;
        const int32_t adj = adjacency[tet][j];
        if (isBoundary(adj)) return surfaceTriangle(adj);
        tet = neighbourTet(adj);
        apex = tets[tet][neighbourFace(adj)];
    }
    return s;
}

namespace {

// 5: regions, and a checksum of the content after the header. The last byte is the version.
constexpr char kMagic[8] = {'T', 'G', 'L', 'W', 'T', 'E', 'T', '5'};
constexpr size_t kHeaderBytes = sizeof kMagic + 2 * sizeof(uint64_t);  // magic, key, checksum

template <class T>
void put(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
void put(std::string& out, const std::vector<T>& v) {
    put(out, uint64_t(v.size()));
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// A cursor over an entry's bytes; every read checks what is left, so a short or lying entry
// fails instead of reading past the end or allocating what a count claims.
struct Reader {
    const std::string& data;
    size_t pos = 0;

    template <class T>
    bool get(T& value) {
        if (data.size() - pos < sizeof value) return false;
        std::memcpy(&value, data.data() + pos, sizeof value);
        pos += sizeof value;
        return true;
    }
    template <class T>
    bool get(std::vector<T>& v) {
        uint64_t n = 0;
        if (!get(n) || n > (data.size() - pos) / sizeof(T)) return false;
        v.resize(n);
        if (n > 0) std::memcpy(v.data(), data.data() + pos, n * sizeof(T));  // an empty vector's data() may be null
        pos += n * sizeof(T);
        return true;
    }
};

// The structure is checked so that an entry cannot send a walk out of bounds or round in circles,
// even one whose checksum matches (by chance, or forged). "" when the mesh holds together.
std::string inconsistency(const TetMesh& m) {
    const size_t ns = m.surface.size();
    if (m.adjacency.size() != m.tets.size() || m.surfaceFace.size() != ns || m.surfaceVertexCount > m.vertices.size() ||
        m.surfaceRegions.size() != ns || m.surfaceFaceFront.size() != ns || m.surfaceSource.size() != ns ||
        m.regionTets.size() != m.regionParent.size() + 1 || m.regionTets.front() != 0 ||
        m.regionTets.back() != m.tets.size() || !std::is_sorted(m.regionTets.begin(), m.regionTets.end()))
        return "array sizes disagree";
    const auto regionOk = [&](int32_t r) { return r >= -1 && r < int32_t(m.regionParent.size()); };
    for (int32_t p : m.regionParent)
        if (!regionOk(p)) return "a region's parent is out of range";
    const uint64_t nv = m.vertices.size(), nt = m.tets.size(), nsv = m.surfaceVertexCount;
    for (size_t t = 0; t < nt; ++t) {
        const auto& v = m.tets[t];
        for (int j = 0; j < 4; ++j) {
            const int32_t a = m.adjacency[t][j];
            if (v[j] >= nv || (a < 0 ? TetMesh::surfaceTriangle(a) >= ns : TetMesh::neighbourTet(a) >= nt))
                return "tet " + std::to_string(t) + " has an index out of range";
        }
        if (v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] || v[2] == v[3])
            return "tet " + std::to_string(t) + " repeats a vertex";
        // A moved vertex that turns a tet inside out would send walks the wrong way (exact sign;
        // Shewchuk's orient3d is negative for the mesh's positive orientation).
        if (!(orient3d(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], m.vertices[v[3]]) < 0))
            return "tet " + std::to_string(t) + " is flat or inside out";
        for (int j = 0; j < 4; ++j) {  // each face is seen the same way from both sides
            const int32_t a = m.adjacency[t][j];
            const uint32_t self = uint32_t(4 * t + j);
            if (a < 0 ? m.surfaceFace[TetMesh::surfaceTriangle(a)] != self &&
                            m.surfaceFaceFront[TetMesh::surfaceTriangle(a)] != self
                      : uint32_t(m.adjacency[TetMesh::neighbourTet(a)][TetMesh::neighbourFace(a)]) != self)
                return "tet " + std::to_string(t) + " has a neighbour that does not point back";
        }
    }
    for (size_t s = 0; s < ns; ++s) {
        if (m.surfaceFace[s] / 4 >= nt || m.surface[s][0] >= nsv || m.surface[s][1] >= nsv || m.surface[s][2] >= nsv ||
            (m.surfaceFaceFront[s] != UINT32_MAX && m.surfaceFaceFront[s] / 4 >= nt))
            return "surface triangle " + std::to_string(s) + " has an index out of range";
        if (m.surfaceRegions[s][0] < 0 || !regionOk(m.surfaceRegions[s][0]) || !regionOk(m.surfaceRegions[s][1]))
            return "surface triangle " + std::to_string(s) + " names a region out of range";
        for (const uint32_t face : {m.surfaceFace[s], m.surfaceFaceFront[s]})
            if (face != UINT32_MAX && m.adjacency[face / 4][face % 4] != int32_t(~uint32_t(s)))
                return "surface triangle " + std::to_string(s) + " is not the face it names";
    }
    return {};
}

}  // namespace

void writeTetMesh(const TetMesh& mesh, uint64_t key, const std::string& path, bool named) {
    std::string body;
    put(body, uint64_t(mesh.surfaceVertexCount));
    put(body, mesh.vertices);
    put(body, mesh.tets);
    put(body, mesh.adjacency);
    put(body, mesh.surface);
    put(body, mesh.surfaceFace);
    put(body, mesh.regionTets);
    put(body, mesh.regionParent);
    put(body, mesh.surfaceRegions);
    put(body, mesh.surfaceFaceFront);
    put(body, mesh.surfaceSource);
    std::string header(kMagic, sizeof kMagic);
    put(header, key);
    put(header, fnv1a(kFnvOffset, body.data(), body.size()));
    // Written beside the target and renamed, so a reader never sees half a file.
    writeStream(
        path, [&](std::ostream& out) { out << header << body; }, named);
}

CacheRead readTetMesh(TetMesh& mesh, uint64_t key, const std::string& path, std::string* problem) {
    const auto damaged = [&](const std::string& why) {
        if (problem) *problem = why;
        return CacheRead::Damaged;
    };
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return CacheRead::Absent;
    std::string data;
    try {
        data = readInputFile(path, kMaxCacheFileBytes, "a tet cache entry");
    } catch (const InputError& e) {
        const std::string what = e.what(), prefix = path + ": ";
        return damaged(what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);  // the caller names the file
    }
    if (data.size() < kHeaderBytes || std::memcmp(data.data(), kMagic, sizeof kMagic - 1) != 0)
        return damaged("not a tetglow cache entry");
    if (data[sizeof kMagic - 1] != kMagic[sizeof kMagic - 1]) return CacheRead::OtherVersion;
    Reader in{data, sizeof kMagic};
    uint64_t storedKey = 0, checksum = 0, nsv = 0;
    in.get(storedKey);
    in.get(checksum);
    if (storedKey != key) return damaged("its key does not match its name");
    if (fnv1a(kFnvOffset, data.data() + kHeaderBytes, data.size() - kHeaderBytes) != checksum)
        return damaged("checksum mismatch");
    TetMesh m;
    if (!in.get(nsv) || !in.get(m.vertices) || !in.get(m.tets) || !in.get(m.adjacency) || !in.get(m.surface) ||
        !in.get(m.surfaceFace) || !in.get(m.regionTets) || !in.get(m.regionParent) || !in.get(m.surfaceRegions) ||
        !in.get(m.surfaceFaceFront) || !in.get(m.surfaceSource) || in.pos != data.size())
        return damaged("truncated or overlong");
    m.surfaceVertexCount = nsv;
    if (const std::string why = inconsistency(m); !why.empty()) return damaged(why);
    mesh = std::move(m);
    return CacheRead::Used;
}

}  // namespace tetglow
