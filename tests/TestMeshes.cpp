#include "TestMeshes.h"

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "scene/MeshFile.h"
#include "tet/Predicates.h"

namespace tetglow::test {

double minAngleDegrees(const TriangleMesh& m) {
    double smallest = 180;
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a = glm::normalize(m.corner(t, (k + 1) % 3) - m.corner(t, k));
            const glm::dvec3 b = glm::normalize(m.corner(t, (k + 2) % 3) - m.corner(t, k));
            smallest = std::min(smallest, std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180 / std::numbers::pi);
        }
    return smallest;
}

bool insideConvex(const TriangleMesh& convex, const glm::dvec3& p) {
    for (uint32_t t = 0; t < convex.triangles.size(); ++t)
        if (orient3d(convex.corner(t, 0), convex.corner(t, 1), convex.corner(t, 2), p) < 0)
            return false;  // above: outside
    return true;
}

double convexChord(const TriangleMesh& convex, const Ray& ray) {
    double t0 = 0, t1 = INFINITY;
    for (uint32_t t = 0; t < convex.triangles.size(); ++t) {
        const glm::dvec3 a = convex.corner(t, 0), n = glm::cross(convex.corner(t, 1) - a, convex.corner(t, 2) - a);
        const double facing = glm::dot(n, ray.d), tPlane = glm::dot(n, a - ray.o) / facing;
        if (facing > 0)
            t1 = std::min(t1, tPlane);
        else if (facing < 0)
            t0 = std::max(t0, tPlane);
        else if (glm::dot(n, a - ray.o) < 0)
            return 0;  // parallel, beyond the face
    }
    return std::max(0.0, t1 - t0);
}

TriangleMesh roundedToFloat(TriangleMesh mesh) {
    for (auto& p : mesh.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
    return mesh;
}

TriangleMesh caplessIcosphere() {
    TriangleMesh m = roundedToFloat(icosphere(3, 1.0));
    std::erase_if(m.triangles,
                  [&](const auto& t) { return m.positions[t[0]].z + m.positions[t[1]].z + m.positions[t[2]].z > 2.7; });
    return m;
}

glm::dvec3 onSphere(std::mt19937_64& rng, double radius) {
    std::normal_distribution<double> n;
    const glm::dvec3 d(n(rng), n(rng), n(rng));
    return radius * d / glm::length(d);
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

void PrintTo(const NamedMesh& m, std::ostream* os) { *os << m.name; }

std::string meshName(const testing::TestParamInfo<NamedMesh>& info) { return info.param.name; }

namespace {
std::filesystem::path testDirOf(const testing::TestInfo& info) {
    return std::filesystem::temp_directory_path() /
           ("tetglow-test-" + std::to_string(::getpid()) + "-" + info.test_suite_name() + "." + info.name());
}

// ctest runs every test in a process of its own, so folders named by process would pile up in
// /tmp run after run: a test's folder goes when it passes (a failure keeps it to look at), the
// process's scratch when the program ends.
class ScratchCleanup : public testing::EmptyTestEventListener {
    void OnTestEnd(const testing::TestInfo& info) override {
        if (!info.result()->Failed()) {
            std::error_code ignored;
            std::filesystem::remove_all(testDirOf(info), ignored);
        }
    }
    void OnTestProgramEnd(const testing::UnitTest&) override {
        std::error_code ignored;
        std::filesystem::remove_all(processScratchDir(), ignored);
    }
};
const bool kScratchCleanup = (testing::UnitTest::GetInstance()->listeners().Append(new ScratchCleanup), true);
}  // namespace

std::string tempDir() {
    // One directory per test, emptied the first time the test asks for it.
    static std::string current;
    const auto dir = testDirOf(*testing::UnitTest::GetInstance()->current_test_info());
    if (current != dir.string()) {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        current = dir.string();
    }
    return current;
}

std::string processScratchDir() {
    return std::filesystem::temp_directory_path() / ("tetglow-run-" + std::to_string(::getpid()));
}

std::string writeTemp(const std::string& name, const std::string& contents) {
    const std::string path = tempDir() + "/" + name;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << contents;
    return path;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string errorOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

std::string readError(const std::string& path, const std::string& node) {
    return errorOf([&] { readMesh(path, nullptr, node); });
}

CommandResult runTetglow(const std::string& args, int timeoutSeconds) {
    const std::string dir = processScratchDir();
    std::filesystem::create_directories(dir);
    const std::string out = dir + "/out", err = dir + "/err";
    // TETGLOW_TEST_BINARY runs the command-line tests against another build, e.g. to see a
    // regression test fail on the code before its fix.
    const char* binary = std::getenv("TETGLOW_TEST_BINARY") ? std::getenv("TETGLOW_TEST_BINARY") : TETGLOW_BINARY;
    const std::string limit = timeoutSeconds > 0 ? "timeout -s KILL " + std::to_string(timeoutSeconds) + " " : "";
    const std::string cmd = std::string("TETGLOW_CACHE_DIR=") + dir + "/cache " + limit + binary + " " + args + " >" +
                            out + " 2>" + err + " </dev/null";
    const int status = std::system(cmd.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return {code, readFile(out), readFile(err)};
}

double testTimeScale() {
    const char* given = std::getenv("TETGLOW_TEST_TIME_SCALE");
    double load[1] = {0};
    const double busy = getloadavg(load, 1) == 1 ? load[0] / std::max(1u, std::thread::hardware_concurrency()) : 1.0;
    return (given ? std::atof(given) : 1.0) * std::max(1.0, busy);
}

void expectOneLineError(const CommandResult& r, int code, const std::string& expected) {
    EXPECT_EQ(r.exitCode, code) << r.err;
    // The error is the last line; progress lines may come before it.
    const size_t start = r.err.rfind("tetglow: error: ");
    ASSERT_NE(start, std::string::npos) << r.err;
    const std::string error = r.err.substr(start);
    EXPECT_NE(error.find(expected), std::string::npos) << "expected '" << expected << "' in: " << error;
    EXPECT_EQ(error.find('\n'), error.size() - 1) << "one line: " << error;
    EXPECT_EQ(r.err.find("tetglow: error: "), start) << "one error: " << r.err;
}

}  // namespace tetglow::test
