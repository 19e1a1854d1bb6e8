// Meshes the tests build themselves, and where to find the others.
#pragma once
#include <functional>
#include <optional>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"
#include "tet/TriangleMesh.h"

namespace tetglow::test {

// The smallest corner angle of any triangle, in degrees.
double minAngleDegrees(const TriangleMesh& m);

// Analytic truth for a convex mesh (outward wound): p inside or on it, by exact plane tests.
bool insideConvex(const TriangleMesh& convex, const glm::dvec3& p);
// The length of the ray (t >= 0, in units of d) inside the convex mesh, by exact-enough plane tests.
double convexChord(const TriangleMesh& convex, const Ray& ray);

// `mesh` with its vertices rounded to float, as the mesh readers round them.
TriangleMesh roundedToFloat(TriangleMesh mesh);
// roundedToFloat(icosphere(3)) without its top cap (about 5% of the area): an open convex
// polyhedron whose closed twin is known.
TriangleMesh caplessIcosphere();
// A point drawn uniformly on the sphere of `radius` about the origin.
glm::dvec3 onSphere(std::mt19937_64& rng, double radius);

// The demo fish and blub, spot, bob from ../shared/meshes (path "" when that folder is absent:
// tests skip those with a message). The parameter of tests run on each (named by meshName).
struct NamedMesh {
    std::string name, path;
};
std::vector<NamedMesh> referenceMeshes();
void PrintTo(const NamedMesh& m, std::ostream* os);
std::string meshName(const testing::TestParamInfo<NamedMesh>& info);
std::string sharedMesh(const std::string& name);  // "" when ../shared/meshes is absent

// A fresh temporary directory for this test.
// Options that always run TetGen (the tests judge TetGen's output, not a cached copy).
inline TetOptions noCache() {
    TetOptions o;
    o.useCache = false;
    return o;
}

// This test's own folder, removed when the test passes.
std::string tempDir();
// This test process's scratch folder (runTetglow's output and tet cache), removed when it ends.
std::string processScratchDir();
// Writes `contents` byte for byte to `name` (which may name sub-folders) in tempDir().
std::string writeTemp(const std::string& name, const std::string& contents);

// The bytes of a file ("" when it cannot be read).
std::string readFile(const std::string& path);

// The message of the InputError `call` throws, or "no error".
std::string errorOf(const std::function<void()>& call);
// readMesh's error message on `path` (only the meshes of `node` where given), or "no error".
std::string readError(const std::string& path, const std::string& node = "");

struct CommandResult {
    int exitCode;
    std::string out, err;
};
// Runs the tetglow binary with the given arguments (shell-quoted by the caller); with a timeout,
// a run that takes longer is killed (exit code 137), so that a test of a hang cannot hang.
CommandResult runTetglow(const std::string& args, int timeoutSeconds = 0);
// How much longer than on a quiet machine a wait for a render may take: TETGLOW_TEST_TIME_SCALE
// (the sanitizer build sets it) times the load average over the cores, when above 1. Waits are
// bounds for something stuck, not measurements.
double testTimeScale();
// A failed command: exit code `code` and one line on stderr that contains `expected`.
void expectOneLineError(const CommandResult& r, int code, const std::string& expected);

}  // namespace tetglow::test
