// Links at the names tetglow writes: a temporary is a new file under a name no one can guess (a
// link planted at the old name, "<output>.<pid>.tmp", chose the file written: in a shared cache
// or farm folder, another user's), a save over a link writes the file it leads to, as editors
// do, a link to nothing is refused rather than replaced, and a numbered save skips a name a link
// holds.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "base/OutputFile.h"
#include "cli/PreviewSaves.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;

void writeText(const std::string& path, const std::string& text) {
    writeStream(path, [&](std::ostream& out) { out << text; });
}

TEST(OutputLinks, ATemporaryIsNotOpenedThroughALinkAtItsOldName) {
    const std::string victim = writeTemp("victim.txt", "the victim's own bytes");
    const std::string out = tempDir() + "/out.png";
    fs::create_symlink(victim, out + "." + std::to_string(::getpid()) + ".tmp");
    writeText(out, "the new output");
    EXPECT_EQ(readFile(victim), "the victim's own bytes") << "the output was written through the planted link";
    EXPECT_FALSE(fs::is_symlink(out));
    EXPECT_EQ(readFile(out), "the new output");
}

TEST(OutputLinks, ACacheEntryIsNotWrittenThroughALinkAtItsTemporarysOldName) {
    TetOptions options;
    options.cacheDir = tempDir() + "/cache";
    TetStats stats;
    tetrahedralize(boxQuads().fanned(), options, &stats);
    ASSERT_FALSE(stats.cacheFile.empty());
    fs::remove(stats.cacheFile);
    const std::string victim = writeTemp("victim.txt", "the victim's own bytes");
    fs::create_symlink(victim, stats.cacheFile + "." + std::to_string(::getpid()) + ".tmp");
    tetrahedralize(boxQuads().fanned(), options, &stats);
    EXPECT_EQ(readFile(victim), "the victim's own bytes") << "the cache entry was written through the planted link";
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(stats.cacheFile)));
}

// A link at a cache entry's own name was planted by someone else: the entry is not written
// through it (the render goes on without the cache).
TEST(OutputLinks, ACacheEntryIsNotWrittenThroughALinkAtItsName) {
    TetOptions options;
    options.cacheDir = tempDir() + "/cache";
    TetStats stats;
    tetrahedralize(boxQuads().fanned(), options, &stats);
    const std::string entry = stats.cacheFile;
    fs::remove(entry);
    const std::string victim = writeTemp("victim.txt", "the victim's own bytes");
    fs::create_symlink(victim, entry);
    tetrahedralize(boxQuads().fanned(), options, &stats);
    EXPECT_EQ(readFile(victim), "the victim's own bytes");
}

TEST(OutputLinks, ASaveOverALinkWritesTheFileItLeadsTo) {
    const std::string target = writeTemp("real/scene.json", "old");
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
    const std::string link = tempDir() + "/scene.json";
    fs::create_symlink("real/scene.json", link);
    writeText(link, "new");
    EXPECT_TRUE(fs::is_symlink(link)) << "the link was replaced by a file";
    EXPECT_EQ(readFile(target), "new");
    EXPECT_EQ(fs::status(target).permissions(), fs::perms::owner_read | fs::perms::owner_write)
        << "the file lost its permissions";
}

TEST(OutputLinks, ALinkToNothingIsRefusedNotReplaced) {
    const std::string link = tempDir() + "/out.json";
    fs::create_symlink("missing/scene.json", link);
    try {
        writeText(link, "new");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), link +
                                             ": is a link to missing/scene.json, which leads to no file (No such file "
                                             "or directory): refusing to write through it");
    }
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_FALSE(fs::exists(tempDir() + "/missing"));
}

// What the user saw: init replaced the link with its scene.
TEST(OutputLinks, InitRefusesAnOutputThatIsALinkToNothing) {
    const std::string mesh = writeTemp("box.obj", objText(boxQuads()));
    const std::string link = tempDir() + "/scene.json";
    fs::create_symlink("elsewhere/scene.json", link);
    const CommandResult r = runTetglow("init '" + mesh + "' -o '" + link + "'");
    expectOneLineError(r, 1, link + ": is a link to elsewhere/scene.json, which leads to no file");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_FALSE(fs::exists(tempDir() + "/elsewhere"));
}

TEST(OutputLinks, ANumberedSaveSkipsANameALinkHolds) {
    const fs::path dir = tempDir();
    cli::PreviewSaves saves(dir, "sphere", 10);
    EXPECT_EQ(saves.next("tuned", {".json"}), (dir / "sphere-tuned-1").string());
    fs::create_symlink("elsewhere/file.json", dir / "sphere-tuned-2.json");  // made after the folder was listed
    EXPECT_EQ(saves.next("tuned", {".json"}), (dir / "sphere-tuned-3").string());
}

}  // namespace
}  // namespace tetglow::test
