// The tet cache: each entry carries a checksum of its content; an entry that is damaged in any
// way is never used, but rebuilt, with one warning naming the file and the problem.
#include <fcntl.h>
#include <sys/stat.h>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "base/Hash.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

constexpr size_t kHeader = 24, kVertexCount = kHeader + 8, kFirstVertex = kVertexCount + 8;  // bytes into an entry

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}
void spit(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Recomputes the checksum, as a forger would: the content checks behind it must hold by themselves.
void reseal(std::string& entry) {
    const uint64_t sum = fnv1a(kFnvOffset, entry.data() + kHeader, entry.size() - kHeader);
    std::memcpy(entry.data() + 16, &sum, 8);
}

struct Cached {
    TetOptions options;
    TetMesh fresh;
    std::string file;
};

// A box tetrahedralized once into this test's own cache folder.
Cached cachedBox() {
    Cached c;
    c.options.cacheDir = test::tempDir() + "/cache";
    TetStats stats;
    c.fresh = tetrahedralize(box(), c.options, &stats);
    EXPECT_FALSE(stats.fromCache);
    c.file = stats.cacheFile;
    EXPECT_TRUE(std::filesystem::is_regular_file(c.file));
    return c;
}

// Tetrahedralizes the box again with the cache as it is now: the entry must not have been used, the
// warning must name `problem`, the result must be the fresh one, and the rebuilt entry must be good.
void expectRebuilt(const Cached& c, const std::string& problem) {
    TetStats stats;
    testing::internal::CaptureStderr();
    const TetMesh again = tetrahedralize(box(), c.options, &stats);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(stats.fromCache);
    EXPECT_EQ(stats.cacheWarning,
              c.file + ": damaged tet cache entry (" + problem + "); not used, tetrahedralizing again");
    EXPECT_EQ(err, "tetglow: warning: " + stats.cacheWarning + "\n");
    EXPECT_EQ(again.vertices, c.fresh.vertices);
    EXPECT_EQ(again.tets, c.fresh.tets);
    TetStats third;
    tetrahedralize(box(), c.options, &third);
    EXPECT_TRUE(third.fromCache) << "the damaged entry was replaced";
    EXPECT_EQ(third.cacheWarning, "");
}

TEST(TetCache, AGoodEntryIsUsedSilently) {
    const Cached c = cachedBox();
    TetStats stats;
    testing::internal::CaptureStderr();
    const TetMesh again = tetrahedralize(box(), c.options, &stats);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_TRUE(stats.fromCache);
    EXPECT_EQ(again.vertices, c.fresh.vertices);
    EXPECT_EQ(again.adjacency, c.fresh.adjacency);
}

// The old cache used an entry whose coordinates had changed: its indices were all in range.
TEST(TetCache, ACorruptedCoordinateIsCaughtByTheChecksum) {
    const Cached c = cachedBox();
    std::string entry = slurp(c.file);
    entry[kFirstVertex + 6] ^= 0x10;
    spit(c.file, entry);
    expectRebuilt(c, "checksum mismatch");
}

TEST(TetCache, TruncatedAndForeignEntriesAreRebuilt) {
    const Cached c = cachedBox();
    const std::string entry = slurp(c.file);
    spit(c.file, entry.substr(0, entry.size() - 1));
    expectRebuilt(c, "checksum mismatch");
    spit(c.file, entry.substr(0, 10));
    expectRebuilt(c, "not a tetglow cache entry");
    spit(c.file, "solid box\n");
    expectRebuilt(c, "not a tetglow cache entry");
    std::string otherKey = entry;
    otherKey[8] ^= 1;
    spit(c.file, otherKey);
    expectRebuilt(c, "its key does not match its name");
}

// Writes `forged` as the cache entry with its checksum recomputed, then expects it rebuilt for `problem`.
void expectForgeryRebuilt(const Cached& c, std::string forged, const std::string& problem) {
    reseal(forged);
    spit(c.file, forged);
    expectRebuilt(c, problem);
}

// Where the tets' vertex indices start in the box's entry.
size_t tetsOffset(const Cached& c) { return kFirstVertex + 24 * c.fresh.vertices.size() + 8; }

TEST(TetCache, ContentChecksHoldBehindAMatchingChecksum) {
    const Cached c = cachedBox();
    const std::string entry = slurp(c.file);
    std::string huge = entry;  // claims 2^40 vertices: refused without allocating them
    const uint64_t count = uint64_t(1) << 40;
    std::memcpy(huge.data() + kVertexCount, &count, 8);
    expectForgeryRebuilt(c, huge, "truncated or overlong");
    std::string badIndex = entry;  // the first tet's first vertex
    const size_t tets = tetsOffset(c);
    const uint32_t far = uint32_t(c.fresh.vertices.size());
    std::memcpy(badIndex.data() + tets, &far, 4);
    expectForgeryRebuilt(c, badIndex, "tet 0 has an index out of range");
    std::string repeated = entry;  // the first tet's second vertex made its first: a flat tet
    std::memcpy(repeated.data() + tets + 4, repeated.data() + tets, 4);
    expectForgeryRebuilt(c, repeated, "tet 0 repeats a vertex");
    std::string oneWay = entry;  // the first tet's face 0 made a boundary face of another surface triangle
    const size_t adjacency = tets + 16 * c.fresh.tets.size() + 8;
    const int32_t other = c.fresh.adjacency[0][0] == ~int32_t(0) ? ~int32_t(1) : ~int32_t(0);
    std::memcpy(oneWay.data() + adjacency, &other, 4);
    expectForgeryRebuilt(c, oneWay, "tet 0 has a neighbour that does not point back");
}

// Two forgeries that keep every index in range: a tet turned inside out (two vertices swapped)
// and a surface vertex moved (the same triangles, another mesh). Both used to be accepted.
TEST(TetCache, AnInsideOutTetOrAMovedVertexIsNotUsed) {
    const Cached c = cachedBox();
    const std::string entry = slurp(c.file);
    const size_t tets = tetsOffset(c);
    std::string insideOut = entry;
    std::memcpy(insideOut.data() + tets, entry.data() + tets + 4, 4);
    std::memcpy(insideOut.data() + tets + 4, entry.data() + tets, 4);
    expectForgeryRebuilt(c, insideOut, "tet 0 is flat or inside out");
    std::string moved = entry;  // vertex 0's x, nudged by one part in 10^6 of the box: no tet flips
    double x = 0;
    std::memcpy(&x, entry.data() + kFirstVertex, 8);
    x += 1e-6;
    std::memcpy(moved.data() + kFirstVertex, &x, 8);
    expectForgeryRebuilt(c, moved, "it holds the tets of another set of meshes");
}

// Found by fuzz_tet_cache: an empty array was copied from a null pointer (UBSan). An entry of
// empty arrays holds together, but it is not this mesh's, and is rebuilt like any collision.
TEST(TetCache, AnEntryOfEmptyArraysIsReadSafelyAndNotUsed) {
    const Cached c = cachedBox();
    // The surface-vertex count and the ten arrays' lengths, all zero.
    std::string empty = slurp(c.file).substr(0, kHeader) + std::string(11 * 8, '\0');
    expectForgeryRebuilt(c, empty, "array sizes disagree");
}

TEST(TetCache, SpecialFilesInTheCacheAreNotRead) {
    const Cached c = cachedBox();
    std::filesystem::remove(c.file);
    ASSERT_EQ(::mkfifo(c.file.c_str(), 0600), 0);  // used to block the reader for ever
    expectRebuilt(c, "is a FIFO, not a regular file");
}

// Another version's entry is only stale: rebuilt without a warning.
TEST(TetCache, AnEntryOfAnotherVersionIsRebuiltSilently) {
    const Cached c = cachedBox();
    std::string entry = slurp(c.file);
    entry[7] = '3';
    spit(c.file, entry);
    TetStats stats;
    testing::internal::CaptureStderr();
    tetrahedralize(box(), c.options, &stats);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_FALSE(stats.fromCache);
    EXPECT_EQ(stats.cacheWarning, "");
    EXPECT_EQ(slurp(c.file)[7], '5') << "rewritten in this version";
}

}  // namespace
}  // namespace tetglow
