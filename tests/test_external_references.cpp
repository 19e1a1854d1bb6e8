// Files a model names besides itself lie in the model's folder: a glTF whose buffer is
// ../outside.bin or an absolute path, a link in the folder that leads out, a pbrt Include or
// plymesh that climbs out. A model from elsewhere read /proc/self/environ that way, and `convert`
// copied its bytes into the OBJ it wrote. TETGLOW_ALLOW_OUTSIDE_REFS=1 lets trusted input do it.
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "base/Error.h"
#include "scene/MeshFile.h"
#include "scene/SceneLoader.h"

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& reference) {
    return "'" + reference +
           "' lies outside the model's folder: refusing to read it (TETGLOW_ALLOW_OUTSIDE_REFS=1 allows it)";
}

// Sets TETGLOW_ALLOW_OUTSIDE_REFS=1 while it lives (the importer's child process inherits it).
class AllowOutside {
public:
    AllowOutside() { ::setenv("TETGLOW_ALLOW_OUTSIDE_REFS", "1", 1); }
    ~AllowOutside() { ::unsetenv("TETGLOW_ALLOW_OUTSIDE_REFS"); }
};

std::string base64(const std::string& bytes) {
    static constexpr char kSymbols[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint8_t(bytes[i + 2]);
        for (size_t k = 0; k < 4; ++k) out += i + k <= bytes.size() ? kSymbols[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

Gltf box(const std::string& uri) { return gltf({boxQuads().fanned()}, {{"Box", 0, {}, ""}}, {0}, uri); }

TEST(ExternalReferences, AGltfBufferOutsideTheModelsFolderIsRefused) {
    const Gltf g = box("../outside.bin");
    writeTemp("outside.bin", g.bin);  // a file the model must not reach: read, it is a valid buffer
    const std::string path = writeTemp("model/box.gltf", g.json);
    EXPECT_EQ(readError(path), path + ": " + refusal("../outside.bin"));
    const AllowOutside allow;
    EXPECT_EQ(readError(path), "no error");
}

// Assimp glues the uri to the folder: an absolute one failed as "<folder>//<uri>: no such file".
TEST(ExternalReferences, AnAbsoluteBufferUriIsNamedAsWritten) {
    const std::string outside = writeTemp("outside.bin", box("").bin);
    const std::string path = writeTemp("model/box.gltf", box(outside).json);
    EXPECT_EQ(readError(path), path + ": " + refusal(outside));
    const AllowOutside allow;
    EXPECT_EQ(readError(path), "no error");
}

TEST(ExternalReferences, ALinkInTheFolderThatLeadsOutIsRefused) {
    writeTemp("outside.bin", box("").bin);
    const std::string path = writeTemp("model/box.gltf", box("buffer.bin").json);
    fs::create_symlink("../outside.bin", tempDir() + "/model/buffer.bin");
    EXPECT_EQ(readError(path), path + ": " + refusal("buffer.bin"));
}

TEST(ExternalReferences, BuffersInTheFolderAndDataUrisAreRead) {
    const Gltf g = box("parts/../parts/box.bin");
    writeTemp("model/parts/box.bin", g.bin);
    EXPECT_EQ(readError(writeTemp("model/box.gltf", g.json)), "no error");
    const Gltf inline_ = box("data:application/octet-stream;base64," + base64(g.bin));
    EXPECT_EQ(readError(writeTemp("model/inline.gltf", inline_.json)), "no error");
}

// What the user saw: convert wrote the outside file's bytes into the OBJ of a medium.
TEST(ExternalReferences, ConvertRefusesAModelThatReadsOutside) {
    const Gltf g = box("../outside.bin");
    writeTemp("outside.bin", g.bin);
    writeTemp("model/box.gltf", g.json);
    const std::string scene = writeTemp("model/scene.json", R"({
      "camera": {"position": [0, 0, 20], "look_at": [0, 0, 0]},
      "lights": [{"type": "environment", "radiance": 1}],
      "media": [{"shape": {"type": "mesh", "file": "box.gltf"}, "sigma_s": 1}]})");
    const CommandResult r = runTetglow("convert '" + scene + "' -o '" + tempDir() + "/out/scene.json'");
    expectOneLineError(r, 1, tempDir() + "/model/box.gltf: " + refusal("../outside.bin"));
    EXPECT_FALSE(fs::exists(tempDir() + "/out/scene-medium-0.obj"));
}

std::string pbrtError(const std::string& path) {
    return errorOf([&] { loadScene(path); });
}

TEST(ExternalReferences, PbrtIncludesAndPlymeshesStayInTheFirstFilesFolder) {
    const std::string head =
        "LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\nLightSource \"point\" \"rgb I\" [1 1 1]\n";
    writeTemp("outside.pbrt", "AttributeBegin\nAttributeEnd\n");
    writeTemp("outside.ply", plyAscii(boxQuads()));
    const std::string include = writeTemp("scene/include.pbrt", head + "Include \"../outside.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(pbrtError(include), include + ":5: Include: " + refusal("../outside.pbrt"));
    const std::string absolute =
        writeTemp("scene/absolute.pbrt", head + "Include \"" + tempDir() + "/outside.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(pbrtError(absolute), absolute + ":5: Include: " + refusal(tempDir() + "/outside.pbrt"));
    // From a file in a sub-folder, "../" is still inside the first file's folder.
    writeTemp("scene/parts/a.pbrt", "Include \"../b.pbrt\"\n");
    writeTemp("scene/b.pbrt", "AttributeBegin\nAttributeEnd\n");
    EXPECT_EQ(pbrtError(writeTemp("scene/nested.pbrt", head + "Include \"parts/a.pbrt\"\nWorldEnd\n")), "no error");
    const std::string ply =
        writeTemp("scene/ply.pbrt", head + "Shape \"plymesh\" \"string filename\" \"../outside.ply\"\nWorldEnd\n");
    EXPECT_EQ(pbrtError(ply), ply + ":5: Shape \"plymesh\": " + refusal("../outside.ply"));
    const AllowOutside allow;
    EXPECT_EQ(pbrtError(include), "no error");
    EXPECT_EQ(pbrtError(ply), "no error");
}

}  // namespace
}  // namespace tetglow::test
