#include "TestMeshes.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace tetglow::test {

TriangleMesh box(glm::dvec3 lo, glm::dvec3 hi) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    // Outward winding, two triangles per face.
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

TriangleMesh icosphere(int subdivisions, double radius, glm::dvec3 centre) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    TriangleMesh m;
    m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (auto& p : m.positions) p = glm::normalize(p);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            return mid[key] = uint32_t(m.positions.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& f : m.triangles) {
            const uint32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
        }
        m.triangles = std::move(next);
    }
    for (auto& p : m.positions) p = centre + p * radius;
    return m;
}

TriangleMesh merge(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh m = a;
    const auto offset = uint32_t(a.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return m;
}

std::string sharedMesh(const std::string& name) {
    const auto path = std::filesystem::path(TETGLOW_SOURCE_DIR) / ".." / "shared" / "meshes" / (name + ".obj");
    return std::filesystem::exists(path) ? path.string() : "";
}

std::vector<NamedMesh> referenceMeshes() {
    std::vector<NamedMesh> meshes{{"fish", std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/fish.obj"}};
    for (const char* name : {"blub", "spot", "bob"}) meshes.push_back({name, sharedMesh(name)});
    return meshes;
}

std::string tempDir() {
    // One directory per test, emptied the first time the test asks for it.
    static std::string current;
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::temp_directory_path() /
                     ("tetglow-test-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "." + info->name());
    if (current != dir.string()) {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        current = dir.string();
    }
    return current;
}

std::string writeTemp(const std::string& name, const std::string& contents) {
    const std::string path = tempDir() + "/" + name;
    std::ofstream(path) << contents;
    return path;
}

CommandResult runTetglow(const std::string& args) {
    const std::string dir = std::filesystem::temp_directory_path() / ("tetglow-run-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string out = dir + "/out", err = dir + "/err";
    const std::string cmd = std::string("TETGLOW_CACHE_DIR=") + dir + "/cache " + TETGLOW_BINARY + " " + args + " >" +
                            out + " 2>" + err + " </dev/null";
    const int status = std::system(cmd.c_str());
    auto slurp = [](const std::string& p) {
        std::ifstream in(p);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return {code, slurp(out), slurp(err)};
}

}  // namespace tetglow::test
