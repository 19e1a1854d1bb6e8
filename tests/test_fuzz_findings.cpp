// What the fuzz targets in fuzz/ found, each as the smallest input that showed it (the tet cache
// reader's finding is in test_tet_cache.cpp, beside the other cache entries).
#include <sys/resource.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "scene/MeshFile.h"

namespace tetglow {
namespace {

// fuzz_obj: a material library name longer than the system allows made std::filesystem::exists
// throw, and the command printed "filesystem error: ... File name too long" instead of going on.
TEST(FuzzFindings, ObjWithAMaterialLibraryNameTooLongForTheSystem) {
    const std::string name(5000, 'm');
    const std::string path =
        test::writeTemp("box.obj", "mtllib " + name + ".mtl\n" +
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
                                       "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
    std::vector<std::string> warnings;
    const TriangleMesh mesh = readMesh(path, &warnings);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("not found; ignored"), std::string::npos) << warnings[0].substr(0, 200);
}

// A triangle in ASCII PLY whose face element is declared by `faceList` and read from `faceLine`:
// readMesh must refuse it with exactly `error` (after the file's path).
void expectTriangleRefused(const std::string& faceList, const std::string& faceLine, const std::string& error) {
    const std::string path = test::writeTemp(
        "tri.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list " +
            faceList + " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" + faceLine + "\n");
    try {
        readMesh(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": " + error);
    }
}

// fuzz_ply: a list length of 7e31 (a float count type) was converted to size_t (UBSan: outside
// the range of representable values); in a Release build the read then ran to the file's end.
TEST(FuzzFindings, PlyListLengthBeyondTheFile) {
    expectTriangleRefused("float int", "7e31 0 1 2", "bad list length in element 'face'");
}

// fuzz_ply: a vertex index of 3.3e32 was converted to int64_t for the error message (UB).
TEST(FuzzFindings, PlyVertexIndexBeyondEveryIntegerType) {
    expectTriangleRefused("uchar float", "3 0 1 3.33333e32",
                          "face 0: vertex index 3.33333e+32 out of range (3 vertices)");
}

// fuzz_off: a face size of 2e9 allocated 8 GB for its indices before reading any of them
// (libFuzzer: out-of-memory, malloc(8000000000)).
TEST(FuzzFindings, OffFaceSizeBeyondTheFile) {
    const std::string path = test::writeTemp("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n");
    try {
        readMesh(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ":6: face of 2000000000 vertices, but only 3 numbers follow");
    }
}

// fuzz_scene_mesh: a character that is not a digit in a Collada index list (<p>0 2\xdf3 ...) makes
// Assimp's parser stop advancing and append indices without end: the import ran, and grew, until
// something killed the process. It is refused at the import's limit for a file this small, 2 GB
// (where the machine allocates fast) or 10 s (where it is busy), not at half the machine's
// memory: on a quiet machine the child reached 2.35 GB in its 10 s under that limit.
TEST(FuzzFindings, ColladaIndexListThatNeverEndsStopsAtTheImportsLimits) {
    const std::string path = TETGLOW_SOURCE_DIR "/fuzz/corpus/scene_mesh/index-list-never-ends.dae";
    try {
        readMesh(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        const std::string importer = path + ": the dae importer (Assimp) ";
        EXPECT_TRUE(e.what() == importer + "ran past its time limit of 10 s" ||
                    e.what() == importer + "ran out of memory (its limit is 2 GB)")
            << e.what();
    }
    rusage children{};
    ::getrusage(RUSAGE_CHILDREN, &children);
    EXPECT_LT(double(children.ru_maxrss) * 1024, 2.2e9) << "the limit, and the test's own memory at the fork";
}

}  // namespace
}  // namespace tetglow
