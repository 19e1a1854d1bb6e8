#include "tet/TetMesh.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <glm/geometric.hpp>

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

int32_t TetMesh::region(uint32_t t) const {
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

constexpr char kMagic[8] = {'T', 'G', 'L', 'W', 'T', 'E', 'T', '4'};  // 4: regions

template <class T>
void put(std::ostream& out, const std::vector<T>& v) {
    const uint64_t n = v.size();
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(T)));
}

template <class T>
bool get(std::istream& in, std::vector<T>& v, uint64_t limit) {
    uint64_t n = 0;
    if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n > limit) return false;
    v.resize(n);
    return bool(in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T))));
}

}  // namespace

void writeTetMesh(const TetMesh& mesh, uint64_t key, const std::string& path) {
    // Written beside the target and renamed, so a reader never sees half a file.
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw InputError(path + ": cannot write tet mesh");
        out.write(kMagic, sizeof kMagic);
        out.write(reinterpret_cast<const char*>(&key), sizeof key);
        const uint64_t nsv = mesh.surfaceVertexCount;
        out.write(reinterpret_cast<const char*>(&nsv), sizeof nsv);
        put(out, mesh.vertices);
        put(out, mesh.tets);
        put(out, mesh.adjacency);
        put(out, mesh.surface);
        put(out, mesh.surfaceFace);
        put(out, mesh.regionTets);
        put(out, mesh.regionParent);
        put(out, mesh.surfaceRegions);
        put(out, mesh.surfaceFaceFront);
        put(out, mesh.surfaceSource);
        if (!out) throw InputError(path + ": write failed");
    }
    std::filesystem::rename(tmp, path);
}

bool readTetMesh(TetMesh& mesh, uint64_t key, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[8];
    uint64_t storedKey = 0, nsv = 0;
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0) return false;
    if (!in.read(reinterpret_cast<char*>(&storedKey), sizeof storedKey) || storedKey != key) return false;
    if (!in.read(reinterpret_cast<char*>(&nsv), sizeof nsv)) return false;
    const uint64_t limit = uint64_t(1) << 32;
    TetMesh m;
    m.surfaceVertexCount = nsv;
    if (!get(in, m.vertices, limit) || !get(in, m.tets, limit) || !get(in, m.adjacency, limit) ||
        !get(in, m.surface, limit) || !get(in, m.surfaceFace, limit) || !get(in, m.regionTets, limit) ||
        !get(in, m.regionParent, limit) || !get(in, m.surfaceRegions, limit) || !get(in, m.surfaceFaceFront, limit) ||
        !get(in, m.surfaceSource, limit))
        return false;
    const size_t ns = m.surface.size();
    if (m.adjacency.size() != m.tets.size() || m.surfaceFace.size() != ns || nsv > m.vertices.size() ||
        m.surfaceRegions.size() != ns || m.surfaceFaceFront.size() != ns || m.surfaceSource.size() != ns ||
        m.regionTets.size() != m.regionParent.size() + 1 || m.regionTets.front() != 0 || m.regionTets.back() != m.tets.size() ||
        !std::is_sorted(m.regionTets.begin(), m.regionTets.end()))
        return false;
    const auto regionOk = [&](int32_t r) { return r >= -1 && r < int32_t(m.regionParent.size()); };
    for (int32_t p : m.regionParent)
        if (!regionOk(p)) return false;
    // Indices are checked so that a damaged file cannot send a walk out of bounds.
    const uint64_t nv = m.vertices.size(), nt = m.tets.size();
    for (size_t t = 0; t < nt; ++t)
        for (int j = 0; j < 4; ++j) {
            const int32_t a = m.adjacency[t][j];
            if (m.tets[t][j] >= nv || (a < 0 ? TetMesh::surfaceTriangle(a) >= ns : TetMesh::neighbourTet(a) >= nt)) return false;
        }
    for (size_t s = 0; s < ns; ++s)
        if (m.surfaceFace[s] / 4 >= nt || m.surface[s][0] >= nsv || m.surface[s][1] >= nsv || m.surface[s][2] >= nsv ||
            (m.surfaceFaceFront[s] != UINT32_MAX && m.surfaceFaceFront[s] / 4 >= nt) || m.surfaceRegions[s][0] < 0 ||
            !regionOk(m.surfaceRegions[s][0]) || !regionOk(m.surfaceRegions[s][1]))
            return false;
    mesh = std::move(m);
    return true;
}

}  // namespace tetglow
