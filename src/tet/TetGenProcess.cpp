#include "tet/TetGenProcess.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <tetgen.h>

namespace tetglow {
namespace {

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
[[noreturn]] void runTetGen(const RegionComplex& complex, const std::string& switches, int fd) {
    const TriangleMesh& mesh = complex.surface;
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
        in.numberofregions = int(complex.seeds.size());
        in.regionlist = complex.seeds.empty() ? nullptr : new REAL[5 * complex.seeds.size()];
        for (size_t r = 0; r < complex.seeds.size(); ++r) {
            for (int k = 0; k < 3; ++k) in.regionlist[5 * r + k] = complex.seeds[r][k];
            in.regionlist[5 * r + 3] = double(r + 1);  // TetGen numbers the cells no seed reaches itself
            in.regionlist[5 * r + 4] = -1;              // no volume bound of its own
        }
        tetgenbehavior b;
        std::vector<char> sw(switches.begin(), switches.end());
        sw.push_back('\0');
        if (!b.parse_commandline(sw.data())) _exit(64);
        tetrahedralize(&b, &in, &out);
        send(fd, out.pointlist, out.numberofpoints * 3);
        send(fd, out.tetrahedronlist, out.numberoftetrahedra * 4);
        send(fd, out.neighborlist, out.numberoftetrahedra * 4);
        const int na = out.numberoftetrahedronattributes;
        std::vector<double> attributes;
        for (int t = 0; na > 0 && t < out.numberoftetrahedra; ++t) attributes.push_back(out.tetrahedronattributelist[t * na]);
        send(fd, attributes.data(), int(attributes.size()));
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

}  // namespace

RawTets runIsolated(const RegionComplex& complex, const std::string& switches) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for TetGen");
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot fork a process for TetGen");
    if (pid == 0) {
        ::close(fds[0]);
        runTetGen(complex, switches, fds[1]);
    }
    ::close(fds[1]);
    RawTets raw;
    const bool ok = receive(fds[0], raw.points) && receive(fds[0], raw.tets) && receive(fds[0], raw.neighbours) &&
                    receive(fds[0], raw.attributes);
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw InputError(tetgenFailure(status));
    if (!ok) throw std::runtime_error("lost TetGen's output");
    return raw;
}

}  // namespace tetglow
