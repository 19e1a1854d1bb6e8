// Every reader goes through readInputFile: special files are refused at once (a FIFO used to
// block, /dev/zero to read for ever), sizes are limited, and nesting cannot crash an error path.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "base/InputFile.h"
#include "render/ImageIO.h"
#include "scene/JsonReader.h"
#include "scene/MeshFile.h"
#include "scene/PbrtParser.h"
#include "scene/SceneLoader.h"

namespace tetglow {
namespace {

using Reader = std::function<void(const std::string&)>;

// The readers, each reading one file named by the path it is given.
const std::vector<std::pair<std::string, Reader>>& readers() {
    static const std::vector<std::pair<std::string, Reader>> all = {
        {"scene.json", [](const std::string& p) { loadScene(p); }},
        {"scene.pbrt", [](const std::string& p) { loadPbrtScene(p); }},
        {"mesh.obj", [](const std::string& p) { readMesh(p); }},
        {"mesh.off", [](const std::string& p) { readMesh(p); }},
        {"mesh.ply", [](const std::string& p) { readMesh(p); }},
        {"image.exr", [](const std::string& p) { readExr(p); }},
    };
    return all;
}

// read(path)'s InputError message, "" with a failure if it throws none. Gives up after 10 s: a
// reader that blocks on a FIFO is released by opening the FIFO's other end, and the test fails.
std::string errorOf(const Reader& read, const std::string& path) {
    std::promise<std::string> result;
    std::thread reader([&] {
        try {
            read(path);
            result.set_value("");
        } catch (const InputError& e) {
            result.set_value(e.what());
        } catch (const std::exception& e) {
            result.set_value(std::string("not an InputError: ") + e.what());
        }
    });
    auto message = result.get_future();
    if (message.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
        ADD_FAILURE() << path << ": the reader blocked";
        ::close(::open(path.c_str(), O_WRONLY | O_NONBLOCK));
    }
    reader.join();
    const std::string m = message.get();
    if (m.empty()) ADD_FAILURE() << path << ": no InputError";
    return m;
}

TEST(InputFiles, ReadsTheBytesUpToTheLimitExactly) {
    const std::string bytes("a\0b\r\n\xff", 6);
    const std::string path = test::writeTemp("x.bin", bytes);
    EXPECT_EQ(readInputFile(path, 6, "a test file"), bytes);
    EXPECT_EQ(readInputFile(path, 6, "a test file").size(), 6u);
    EXPECT_EQ(errorOf([](const std::string& p) { readInputFile(p, 5, "a test file"); }, path),
              path + ": 6 bytes, larger than the 5 bytes limit for a test file");
    EXPECT_EQ(errorOf([](const std::string& p) { readInputFile(p, 5, "a test file"); }, path + "-absent"),
              path + "-absent: no such file");
}

// /proc files claim size 0: the limit holds while reading, not only against what stat says.
TEST(InputFiles, AFileWithoutASizeIsStillLimited) {
    EXPECT_EQ(readInputFile("/proc/self/comm", 4096, "a test file").back(), '\n');
    const std::string error =
        errorOf([](const std::string& p) { readInputFile(p, 2, "a test file"); }, "/proc/self/comm");
    EXPECT_EQ(error, "/proc/self/comm: more than 2 bytes, larger than the 2 bytes limit for a test file");
}

TEST(InputFiles, EveryReaderRefusesAFifoAtOnce) {
    for (const auto& [name, read] : readers()) {
        const std::string path = test::tempDir() + "/fifo-" + name;
        ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
        EXPECT_EQ(errorOf(read, path), path + ": is a FIFO, not a regular file");
    }
}

TEST(InputFiles, EveryReaderRefusesDevicesAndFolders) {
    for (const auto& [name, read] : readers()) {
        SCOPED_TRACE(name);
        EXPECT_EQ(errorOf(read, "/dev/null"), "/dev/null: is a character device, not a regular file");
        const std::string dir = test::tempDir() + "/folder-" + name;
        std::filesystem::create_directories(dir);
        EXPECT_EQ(errorOf(read, dir), dir + ": is a directory, not a regular file");
    }
}

// Sparse files: the size is refused before a byte is read, so the test costs no disk or memory.
TEST(InputFiles, EveryReaderHasASizeLimit) {
    const std::vector<std::pair<std::string, std::string>> limits = {
        {"scene.json", "65 MiB, larger than the 64 MiB limit for a scene file"},
        {"scene.pbrt", "65 MiB, larger than the 64 MiB limit for a pbrt file"},
        {"mesh.obj", "1025 MiB, larger than the 1024 MiB limit for a mesh"},
        {"mesh.off", "1025 MiB, larger than the 1024 MiB limit for a mesh"},
        {"mesh.ply", "1025 MiB, larger than the 1024 MiB limit for a mesh"},
        {"image.exr", "1025 MiB, larger than the 1024 MiB limit for an OpenEXR image"},
    };
    for (const auto& [name, read] : readers()) {
        const std::string path = test::writeTemp("big-" + name, "");
        const bool scene = name.rfind("scene", 0) == 0;
        ASSERT_EQ(::truncate(path.c_str(), off_t((scene ? 65 : 1025) * kMiB)), 0);
        std::string expected;
        for (const auto& [n, e] : limits)
            if (n == name) expected = path + ": " + e;
        EXPECT_EQ(errorOf(read, path), expected);
    }
}

TEST(InputFiles, IncludeAndPlymeshGoThroughTheSameChecks) {
    const std::string dir = test::tempDir();
    ASSERT_EQ(::mkfifo((dir + "/part.pbrt").c_str(), 0600), 0);
    ASSERT_EQ(::mkfifo((dir + "/mesh.ply").c_str(), 0600), 0);
    const std::string include = test::writeTemp("include.pbrt", "WorldBegin\nInclude \"part.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(errorOf([](const std::string& p) { loadPbrtScene(p); }, include),
              include + ":2: Include: " + dir + "/part.pbrt: is a FIFO, not a regular file");
    const std::string ply =
        test::writeTemp("ply.pbrt", "WorldBegin\nShape \"plymesh\" \"string filename\" \"mesh.ply\"\nWorldEnd\n");
    EXPECT_NE(errorOf([](const std::string& p) { loadPbrtScene(p); }, ply)
                  .find(dir + "/mesh.ply: is a FIFO, not a regular file"),
              std::string::npos);
}

// An EXR header is small, but its data window sizes the image: the old reader allocated what
// any header claimed (10000 x 10000 float RGB: 1.2 GB for a 400-byte file).
TEST(InputFiles, AnExrHeaderClaimingAHugeImageIsRefusedBeforeAllocating) {
    const std::string path = test::tempDir() + "/small.exr";
    writeExr(path, Image(4, 4));
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    const std::string attribute("dataWindow\0box2i\0", 17);
    const size_t at = bytes.find(attribute);
    ASSERT_NE(at, std::string::npos);
    const auto claim = [&](int32_t width, int32_t height) {
        std::string patched = bytes;
        const int32_t window[4] = {0, 0, width - 1, height - 1};
        std::memcpy(patched.data() + at + attribute.size() + 4, window, sizeof window);
        patched.append(8 * size_t(height), '\0');  // room for the line offsets that the header implies
        return test::writeTemp("claims.exr", patched);
    };
    EXPECT_NO_THROW(readExr(claim(4, 4)));
    const std::string tooMany = claim(10000, 10000);
    EXPECT_EQ(
        errorOf([](const std::string& p) { readExr(p); }, tooMany),
        tooMany + ": the header claims 10000 x 10000 pixels; at most 67108864 pixels (and 16384 per side) are read");
    const std::string tooWide = claim(100000, 1);
    EXPECT_NE(errorOf([](const std::string& p) { readExr(p); }, tooWide).find(tooWide + ": cannot read: "),
              std::string::npos);
}

// Printing a value in an error message recursed once per level: 100000 levels overflowed the stack.
TEST(InputFiles, DeeplyNestedJsonIsAnErrorNotACrash) {
    const std::string path =
        test::writeTemp("deep.json", "{\"camera\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
    const auto r = test::runTetglow("render " + path);
    EXPECT_EQ(r.exitCode, 1) << r.err.substr(0, 300);
    EXPECT_NE(r.err.find(": /camera/0/0/0/"), std::string::npos) << r.err.substr(0, 300);
    EXPECT_NE(r.err.find(": nested deeper than 64 arrays and objects\n"), std::string::npos) << r.err.substr(0, 300);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
    // 64 levels are read (and then refused for what they are, not for their depth).
    const std::string ok = std::string(63, '[') + std::string(63, ']');
    EXPECT_NO_THROW(parseJson("{\"a\": " + ok + "}", "ok.json"));
    EXPECT_THROW(parseJson("{\"a\": [" + ok + "]}", "deep.json"), InputError);
}

}  // namespace
}  // namespace tetglow
