#include "tet/Tetrahedralizer.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <glm/common.hpp>
#include <tetgen.h>

#include "tet/Hash.h"
#include "tet/Predicates.h"

namespace tetglow {

std::string TetOptions::switches() const {
    std::string s = "pYnQz";
    char buf[64];
    if (radiusEdgeRatio > 0) s += (std::snprintf(buf, sizeof buf, "q%.17g", radiusEdgeRatio), buf);
    if (maxVolume > 0) s += (std::snprintf(buf, sizeof buf, "a%.17g", maxVolume), buf);
    return s;
}

namespace {

// What TetGen hands back from the child process.
struct RawTets {
    std::vector<double> points;
    std::vector<int> tets, neighbours;
};

void writeAll(int fd, const void* data, size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        ssize_t w = ::write(fd, p, n);
        if (w <= 0) _exit(70);
        p += w;
        n -= size_t(w);
    }
}

template <class T>
void send(int fd, const T* data, int count) {
    const int64_t n = count;
    writeAll(fd, &n, sizeof n);
    writeAll(fd, data, sizeof(T) * size_t(count));
}

// In the child: run TetGen and stream the result; never returns.
[[noreturn]] void runTetGen(const TriangleMesh& mesh, const std::string& switches, int fd) {
    int devnull = ::open("/dev/null", O_WRONLY);  // TetGen prints to stdout even when quiet
    if (devnull >= 0) ::dup2(devnull, STDOUT_FILENO);
    try {
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
        tetgenbehavior b;
        std::vector<char> sw(switches.begin(), switches.end());
        sw.push_back('\0');
        if (!b.parse_commandline(sw.data())) _exit(64);
        tetrahedralize(&b, &in, &out);
        send(fd, out.pointlist, out.numberofpoints * 3);
        send(fd, out.tetrahedronlist, out.numberoftetrahedra * 4);
        send(fd, out.neighborlist, out.numberoftetrahedra * 4);
        _exit(0);
    } catch (int code) {
        _exit(code >= 1 && code <= 10 ? code : 11);
    } catch (...) {
        _exit(12);
    }
}

bool readAll(int fd, void* data, size_t n) {
    char* p = static_cast<char*>(data);
    while (n > 0) {
        ssize_t r = ::read(fd, p, n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        p += r;
        n -= size_t(r);
    }
    return true;
}

template <class T>
bool receive(int fd, std::vector<T>& v) {
    int64_t n = 0;
    if (!readAll(fd, &n, sizeof n) || n < 0 || n > (int64_t(1) << 34)) return false;
    v.resize(size_t(n));
    return readAll(fd, v.data(), sizeof(T) * v.size());
}

std::string tetgenFailure(int status) {
    if (WIFSIGNALED(status))
        return std::string("TetGen crashed (") + strsignal(WTERMSIG(status)) +
               ") on this mesh; it likely has nearly touching or intersecting faces";
    switch (WEXITSTATUS(status)) {
        case 1: return "TetGen ran out of memory";
        case 2: return "TetGen hit an internal error on this mesh";
        case 3: return "TetGen found self-intersecting faces";
        case 4: return "TetGen found a feature too small to resolve (nearly touching faces)";
        case 5: return "TetGen found two facets too close to each other";
        case 10: return "TetGen rejected the input";
        case 64: return "TetGen rejected the switches";
        default: return "TetGen failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
    }
}

RawTets runIsolated(const TriangleMesh& mesh, const std::string& switches) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for TetGen");
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot fork a process for TetGen");
    if (pid == 0) {
        ::close(fds[0]);
        runTetGen(mesh, switches, fds[1]);
    }
    ::close(fds[1]);
    RawTets raw;
    const bool ok = receive(fds[0], raw.points) && receive(fds[0], raw.tets) && receive(fds[0], raw.neighbours);
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw InputError(tetgenFailure(status));
    if (!ok) throw std::runtime_error("lost TetGen's output");
    return raw;
}

std::array<uint32_t, 3> sortedFace(const std::array<uint32_t, 4>& v, int j) {
    std::array<uint32_t, 3> f{v[kInwardFace[j][0]], v[kInwardFace[j][1]], v[kInwardFace[j][2]]};
    std::sort(f.begin(), f.end());
    return f;
}

// Builds the TetMesh: positive orientation, encoded adjacency, boundary faces <-> surface
// triangles. Regions enclosed by surface triangles but outside the medium (cavities TetGen
// filled) are removed: a region is kept when its tets lie behind the outward surface normals.
TetMesh assemble(const TriangleMesh& surface, const RawTets& raw) {
    const size_t nv = raw.points.size() / 3, nt = raw.tets.size() / 4;
    if (nt == 0) throw InputError("TetGen produced no tetrahedra (is the mesh closed?)");
    if (nv < surface.positions.size()) throw InputError("TetGen dropped input vertices");
    TetMesh m;
    m.vertices.resize(nv);
    for (size_t i = 0; i < nv; ++i) m.vertices[i] = {raw.points[3 * i], raw.points[3 * i + 1], raw.points[3 * i + 2]};
    for (size_t i = 0; i < surface.positions.size(); ++i)
        if (m.vertices[i] != surface.positions[i]) throw InputError("TetGen moved input vertex " + std::to_string(i));

    std::vector<std::array<uint32_t, 4>> tets(nt);
    std::vector<std::array<int, 4>> nbr(nt);
    for (size_t t = 0; t < nt; ++t)
        for (int j = 0; j < 4; ++j) {
            tets[t][j] = uint32_t(raw.tets[4 * t + j]);
            nbr[t][j] = raw.neighbours[4 * t + j];
            if (tets[t][j] >= nv || nbr[t][j] >= int(nt)) throw InputError("TetGen returned an index out of range");
        }
    for (size_t t = 0; t < nt; ++t) {
        const auto& v = tets[t];
        const double o = orient3d(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], m.vertices[v[3]]);
        if (o == 0) throw InputError("TetGen produced a flat tetrahedron " + std::to_string(t));
        if (o > 0) {  // Shewchuk's orient3d is negative for our positive orientation
            std::swap(tets[t][0], tets[t][1]);
            std::swap(nbr[t][0], nbr[t][1]);
        }
    }

    std::map<std::array<uint32_t, 3>, uint32_t> surfaceIndex;
    for (uint32_t s = 0; s < surface.triangles.size(); ++s) {
        auto f = surface.triangles[s];
        std::sort(f.begin(), f.end());
        surfaceIndex.emplace(f, s);
    }
    // Per tet face: the surface triangle it coincides with, or -1.
    std::vector<std::array<int64_t, 4>> onSurface(nt);
    for (size_t t = 0; t < nt; ++t)
        for (int j = 0; j < 4; ++j) {
            auto it = surfaceIndex.find(sortedFace(tets[t], j));
            onSurface[t][j] = it == surfaceIndex.end() ? -1 : int64_t(it->second);
        }

    // Flood regions across faces that are not surface triangles; keep the inside ones.
    std::vector<int> region(nt, -1), keepRegion;
    std::vector<uint32_t> stack;
    for (uint32_t seed = 0; seed < nt; ++seed) {
        if (region[seed] >= 0) continue;
        const int id = int(keepRegion.size());
        keepRegion.push_back(-1);  // undecided
        region[seed] = id;
        stack.push_back(seed);
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            for (int j = 0; j < 4; ++j) {
                if (onSurface[t][j] >= 0) {
                    const auto& s = surface.triangles[size_t(onSurface[t][j])];
                    const bool inside = orient3d(m.vertices[s[0]], m.vertices[s[1]], m.vertices[s[2]],
                                                 m.vertices[tets[t][j]]) > 0;
                    if (keepRegion[id] >= 0 && keepRegion[id] != int(inside))
                        throw InputError("the surface does not separate inside from outside consistently");
                    keepRegion[id] = inside;
                } else if (nbr[t][j] >= 0 && region[nbr[t][j]] < 0) {
                    region[nbr[t][j]] = id;
                    stack.push_back(uint32_t(nbr[t][j]));
                }
            }
        }
    }

    // Kept tets in Morton order of their centroids: a walk's next tet is then usually close in
    // memory (TetGen's order is not spatial).
    Bounds3 box;
    for (const auto& v : m.vertices) box.extend(v);
    const glm::dvec3 scale = 1023.0 / glm::max(box.hi - box.lo, glm::dvec3(1e-300));
    auto spread = [](uint64_t x) {  // 10 bits -> every third of 30
        x = (x | (x << 16)) & 0x030000FF;
        x = (x | (x << 8)) & 0x0300F00F;
        x = (x | (x << 4)) & 0x030C30C3;
        return (x | (x << 2)) & 0x09249249;
    };
    std::vector<std::pair<uint64_t, uint32_t>> order;
    for (uint32_t t = 0; t < nt; ++t) {
        if (keepRegion[region[t]] != 1) continue;
        const auto& v = tets[t];
        const glm::dvec3 c = (m.vertices[v[0]] + m.vertices[v[1]] + m.vertices[v[2]] + m.vertices[v[3]]) * 0.25;
        const glm::dvec3 q = glm::clamp((c - box.lo) * scale, 0.0, 1023.0);
        order.push_back({spread(uint64_t(q.x)) | spread(uint64_t(q.y)) << 1 | spread(uint64_t(q.z)) << 2, t});
    }
    std::sort(order.begin(), order.end());
    std::vector<int64_t> newIndex(nt, -1);
    for (const auto& [code, t] : order) {
        newIndex[t] = int64_t(m.tets.size());
        m.tets.push_back(tets[t]);
    }
    m.adjacency.resize(m.tets.size());
    m.surface = surface.triangles;
    m.surfaceVertexCount = surface.positions.size();
    m.surfaceFace.assign(surface.triangles.size(), UINT32_MAX);
    for (size_t t = 0; t < nt; ++t) {
        if (newIndex[t] < 0) continue;
        const auto nt_ = uint32_t(newIndex[t]);
        for (int j = 0; j < 4; ++j) {
            if (onSurface[t][j] >= 0) {
                const auto s = size_t(onSurface[t][j]);
                if (m.surfaceFace[s] != UINT32_MAX) throw InputError("surface triangle " + std::to_string(s) + " bounds two tets");
                m.surfaceFace[s] = 4 * nt_ + uint32_t(j);
                m.adjacency[nt_][j] = ~int32_t(s);
                continue;
            }
            const int n = nbr[t][j];
            if (n < 0 || newIndex[n] < 0)
                throw InputError("TetGen left an unmatched boundary face: the boundary was not preserved");
            int back = 0;
            while (back < 4 && nbr[n][back] != int(t)) ++back;
            if (back == 4) throw InputError("TetGen returned non-reciprocal neighbours");
            m.adjacency[nt_][j] = int32_t(4 * newIndex[n] + back);
        }
    }
    for (size_t s = 0; s < m.surfaceFace.size(); ++s)
        if (m.surfaceFace[s] == UINT32_MAX) throw InputError("surface triangle " + std::to_string(s) + " bounds no tet");
    return m;
}

uint64_t cacheKey(const TriangleMesh& mesh, const std::string& switches) {
    uint64_t h = kFnvOffset;
    h = fnv1a(h, mesh.positions.data(), mesh.positions.size() * sizeof(mesh.positions[0]));
    h = fnv1a(h, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
    h = fnv1a(h, switches.data(), switches.size());
    return h;
}

std::filesystem::path cacheDirectory(const TetOptions& options) {
    if (!options.cacheDir.empty()) return options.cacheDir;
    if (const char* d = std::getenv("TETGLOW_CACHE_DIR"); d && *d) return d;
    if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "tetglow";
    if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "tetglow";
    return {};
}

}  // namespace

TetMesh tetrahedralizeUnchecked(const TriangleMesh& surface, const std::string& switches) {
    return assemble(surface, runIsolated(surface, switches));
}

TetMesh tetrahedralize(TriangleMesh surface, const TetOptions& options, TetStats* stats, ValidationReport* report) {
    const auto start = std::chrono::steady_clock::now();
    ValidationReport validation = validateAndRepair(surface);
    if (report) *report = validation;
    const std::string switches = options.switches();
    const uint64_t key = cacheKey(surface, switches);
    TetStats local;
    std::filesystem::path file;
    if (options.useCache) {
        if (auto dir = cacheDirectory(options); !dir.empty()) {
            char name[32];
            std::snprintf(name, sizeof name, "%016llx.tet", static_cast<unsigned long long>(key));
            file = dir / name;
        }
    }
    TetMesh mesh;
    std::string problem;
    CacheRead cached = file.empty() ? CacheRead::Absent : readTetMesh(mesh, key, file.string(), &problem);
    if (cached == CacheRead::Used && mesh.surface != surface.triangles)
        cached = CacheRead::Damaged, problem = "it holds the tets of another mesh";  // a key collision
    if (cached == CacheRead::Used) {
        local.fromCache = true;
        local.cacheFile = file.string();
    } else {
        if (cached == CacheRead::Damaged) {
            local.cacheWarning = file.string() + ": damaged tet cache entry (" + problem + "); not used, tetrahedralizing again";
            std::fprintf(stderr, "tetglow: warning: %s\n", local.cacheWarning.c_str());
        }
        mesh = tetrahedralizeUnchecked(surface, switches);
        if (!file.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(file.parent_path(), ec);
            try {
                writeTetMesh(mesh, key, file.string());
                local.cacheFile = file.string();
            } catch (const std::exception&) {
                // An unwritable cache only costs time on the next run.
            }
        }
    }
    local.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = local;
    return mesh;
}

}  // namespace tetglow
