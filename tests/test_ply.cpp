// PLY files as pbrt-v3's "plymesh" and every other mesh shape read them: ascii and both binary
// byte orders give the same mesh, polygons fanned (a quad into the two triangles pbrt-v3 makes).
#include <algorithm>
#include <bit>
#include <cstring>
#include <sstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "scene/MeshFile.h"
#include "scene/PlyReader.h"

namespace tetglow {
namespace {

const double kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
// Counter-clockwise seen from outside; and a pentagon (pbrt-v3 skips it: tetglow fans it too).
const std::vector<std::vector<int>> kFaces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},   {2, 6, 7, 3},
                                              {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 3, 2, 6}};

std::string asciiPly() {
    std::string s =
        "ply\nformat ascii 1.0\ncomment a unit cube\nelement vertex 8\nproperty float x\nproperty float y\nproperty "
        "float z\n"
        "property float nx\nproperty float ny\nproperty float nz\nelement face 7\nproperty list uchar int "
        "vertex_indices\nend_header\n";
    // A stream, not chained std::string +, which trips GCC 12's false -Wrestrict warning.
    std::ostringstream body;
    for (const auto& c : kCorners) body << c[0] << ' ' << c[1] << ' ' << c[2] << " 0 0 1\n";
    for (const auto& f : kFaces) {
        body << f.size();
        for (int v : f) body << ' ' << v;
        body << '\n';
    }
    return s + body.str();
}

// Bytes of `x` as type T in the given byte order.
template <class T>
void put(std::string& out, double x, bool little) {
    const T v = T(x);
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    if (little != (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof b);
    out.append(b, sizeof b);
}

// Other types, an extra scalar before the list, and an element the reader must step over.
std::string binaryPly(bool little) {
    std::string s =
        std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
        " 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\n"
        "element face 7\nproperty uchar flags\nproperty list ushort uint vertex_index\n"
        "element edge 1\nproperty int vertex1\nproperty list uchar short more\nend_header\n";
    for (const auto& c : kCorners) {
        for (double x : c) put<double>(s, x, little);
        put<uint8_t>(s, 200, little);
    }
    for (const auto& f : kFaces) {
        put<uint8_t>(s, 7, little);
        put<uint16_t>(s, double(f.size()), little);
        for (int v : f) put<uint32_t>(s, v, little);
    }
    put<int32_t>(s, 3, little);
    put<uint8_t>(s, 2, little);
    put<int16_t>(s, -1, little);
    put<int16_t>(s, 5, little);
    return s;
}

TEST(PbrtPly, AsciiAndBinaryGiveTheSameCube) {
    const MeshFile ascii = readMeshFile(test::writeTemp("a.ply", asciiPly()));
    ASSERT_EQ(ascii.mesh.positions.size(), 8u);
    ASSERT_EQ(ascii.mesh.triangles.size(), 15u);  // six quads, the pentagon's three
    ASSERT_EQ(ascii.normals.size(), 8u);
    EXPECT_EQ(ascii.normals[3], glm::dvec3(0, 0, 1));
    // The fan of quad (a b c d): (a b c) and (a c d), the triangles of pbrt-v3's (a b c), (d a c).
    EXPECT_EQ(ascii.mesh.triangles[0], (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(ascii.mesh.triangles[1], (std::array<uint32_t, 3>{0, 3, 1}));
    EXPECT_EQ(ascii.mesh.triangles[14], (std::array<uint32_t, 3>{0, 2, 6}));
    EXPECT_NEAR(signedVolume(ascii.mesh), 1, 1e-12);  // the pentagon lies in planes through vertex 0

    for (bool little : {true, false}) {
        const MeshFile binary = readMeshFile(test::writeTemp("b.ply", binaryPly(little)));
        EXPECT_EQ(binary.mesh.positions, ascii.mesh.positions) << little;
        EXPECT_EQ(binary.mesh.triangles, ascii.mesh.triangles) << little;
        EXPECT_TRUE(binary.normals.empty());
    }
}

TEST(PbrtPly, BrokenFilesAreErrors) {
    const std::string path = "bad.ply";
    auto error = [&](const std::string& bytes) {
        try {
            parsePly(bytes, path);
        } catch (const InputError& e) {
            return std::string(e.what()).substr(path.size());
        }
        return std::string("no error");
    };
    std::string outOfRange = asciiPly();
    outOfRange.replace(outOfRange.rfind("5 0 1 3 2 6"), 11, "3 0 1 9");
    EXPECT_EQ(error(outOfRange), ": face 6: vertex index 9 out of range (8 vertices)");
    EXPECT_EQ(error(asciiPly().substr(0, asciiPly().size() - 20)), ": ends early, in element 'face'");
    EXPECT_EQ(error(binaryPly(true).substr(0, 400)), ": ends early, in element 'vertex'");
    EXPECT_EQ(error("OFF\n"), ": not a PLY file (it must start with 'ply')");
    EXPECT_EQ(error("ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n"),
              ": PLY header: unknown property type 'half'");
    EXPECT_EQ(error("ply\nformat ascii 1.0\nelement vertex 1\n"), ": PLY header without 'end_header'");
}

}  // namespace
}  // namespace tetglow
