// Image files and image comparison: EXR round trips, PNG previews, compare() and `tetglow diff`.
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <OpenEXR/ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <png.h>
#include <nlohmann/json.hpp>

#include "TestMeshes.h"
#include "render/ImageIO.h"

namespace tetglow {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Runs f and returns the InputError message it throws ("" and a failure if it throws none).
template <class F>
std::string inputError(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

Image gradient(int w, int h, float scale) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.at(x, y) = scale * glm::vec3(x + 0.1f, y / 3.0f, -1e-30f * x);
    return image;
}

void expectBitIdentical(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)), 0);
}

// A test image and its reference, 3x2, with the expected differences worked out by hand below.
struct Pair {
    Image test{3, 2}, reference{3, 2};
};
Pair handPair() {
    Pair p;
    p.test.at(0, 0) = {0.5f, 0.5f, 0.5f};
    p.reference.at(0, 0) = {0, 0, 1};  // errors .5 .5 .5
    p.test.at(1, 0) = {kNaN, 0, 0};    // non-finite
    p.test.at(2, 0) = {0, kInf, 0};    // non-finite
    p.test.at(0, 1) = {1, 1, 1};
    p.reference.at(0, 1) = {1, 1, 1};  // errors 0 0 0
    p.test.at(1, 1) = {1, 2, 3};
    p.reference.at(1, 1) = {1, 1, 1};  // errors 0 1 2: the largest
    p.test.at(2, 1) = {0, 0, 0};       // errors 0 0 0
    return p;
}
// Over the 4 finite pixels, 12 samples.
const double kRmse = std::sqrt((3 * 0.25 + 1 + 4) / 12), kMae = (1.5 + 3.0) / 12;
const double kRelMse = (2 * 0.25 / 0.01 + 0.25 / 1.01 + 1 / 1.01 + 4 / 1.01) / 12;

TEST(Image, ExrRoundTripIsBitExactWithLayers) {
    const Image rgb = gradient(7, 5, 1.0f), direct = gradient(7, 5, 3e20f), indirect = gradient(7, 5, 1e-3f);
    const std::string path = test::tempDir() + "/x.exr";
    writeExr(path, rgb, {{"direct", &direct}, {"indirect", &indirect}});
    expectBitIdentical(readExr(path), rgb);
    expectBitIdentical(readExr(path, "direct"), direct);
    expectBitIdentical(readExr(path, "indirect"), indirect);
    const std::string message = inputError([&] { readExr(path, "albedo"); });
    EXPECT_NE(message.find("missing channels albedo.R, albedo.G, albedo.B"), std::string::npos) << message;
    EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(Image, ReadsHalfExr) {
    const std::string path = test::tempDir() + "/half.exr";
    {
        Imf::Rgba pixels[2] = {Imf::Rgba(0.5f, 1.25f, 2048.0f, 1.0f), Imf::Rgba(-3.0f, 0.0f, 0.099975586f, 1.0f)};
        Imf::RgbaOutputFile file(path.c_str(), 2, 1, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels, 1, 2);
        file.writePixels(1);
    }
    const Image image = readExr(path);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f, 1.25f, 2048.0f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(-3.0f, 0.0f, 0.099975586f));  // exactly representable in half
}

TEST(Image, UnreadableFilesAreInputErrors) {
    const std::string missing = test::tempDir() + "/missing.exr";
    EXPECT_NE(inputError([&] { readExr(missing); }).find(missing + ": no such file"), std::string::npos);
    const std::string text = test::writeTemp("text.exr", "not an image\n");
    EXPECT_NE(inputError([&] { readExr(text); }).find(text + ": not an OpenEXR file"), std::string::npos);
    // A real EXR cut short: the header reads, the pixels do not.
    const std::string cut = test::tempDir() + "/cut.exr";
    writeExr(cut, gradient(64, 64, 1.0f));
    std::filesystem::resize_file(cut, std::filesystem::file_size(cut) / 2);
    EXPECT_NE(inputError([&] { readExr(cut); }).find(cut), std::string::npos);
}

TEST(Image, FailedWritesLeaveNoFile) {
    const std::string noDir = test::tempDir() + "/no/such/dir/x.exr";
    EXPECT_NE(inputError([&] { writeExr(noDir, gradient(2, 2, 1)); }).find(noDir), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(noDir));
    // The target is a directory: the temporary file is written, the rename fails and it is removed.
    const std::string dir = test::tempDir() + "/taken.png";
    std::filesystem::create_directory(dir);
    EXPECT_NE(inputError([&] { writePng(dir, gradient(2, 2, 1)); }).find(dir), std::string::npos);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(test::tempDir()), {}), 1);
}

TEST(Image, CompareHandComputed) {
    const Pair p = handPair();
    const ImageDiff d = compare(p.test, p.reference);
    EXPECT_NEAR(d.rmse, kRmse, 1e-15);
    EXPECT_NEAR(d.relMse, kRelMse, 1e-13);
    EXPECT_NEAR(d.mae, kMae, 1e-15);
    EXPECT_EQ(d.maxError, 2.0);
    EXPECT_EQ(d.maxX, 1);
    EXPECT_EQ(d.maxY, 1);
    EXPECT_EQ(d.nonFinite, 2u);

    const ImageDiff same = compare(p.reference, p.reference);
    EXPECT_EQ(same.rmse, 0);
    EXPECT_EQ(same.relMse, 0);
    EXPECT_EQ(same.maxError, 0);
    EXPECT_EQ(same.nonFinite, 0u);
}

TEST(Image, CompareRejectsMismatchAndNanReference) {
    const std::string message = inputError([] { compare(Image(3, 2), Image(2, 3)); });
    EXPECT_NE(message.find("3x2"), std::string::npos) << message;
    EXPECT_NE(message.find("2x3"), std::string::npos) << message;
    Image reference(2, 2);
    reference.at(1, 0).y = kNaN;
    EXPECT_NE(inputError([&] { compare(Image(2, 2), reference); }).find("pixel (1, 0)"), std::string::npos);
}

// The sRGB OETF, to 8 bits, as the preview should apply it.
int srgb8(double v) {
    return int(std::lround(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055)));
}

TEST(Image, PngPreview) {
    Image image(4, 2);
    image.at(0, 0) = {0, 0.25f, 0.5f};
    image.at(1, 0) = {0.001f, 0.1f, -1};  // negative: black
    image.at(2, 0) = {8, 4, 1};           // overexposed: divided by 8/2, hue kept
    image.at(3, 0) = {kNaN, 0, 0};        // magenta
    image.at(0, 1) = {0.2f, kInf, 0};     // magenta
    const std::string path = test::tempDir() + "/x.png";
    writePng(path, image, 1.0);  // exposure 1: twice as bright

    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    ASSERT_TRUE(png_image_begin_read_from_file(&png, path.c_str())) << png.message;
    EXPECT_EQ(png.width, 4u);
    EXPECT_EQ(png.height, 2u);
    png.format = PNG_FORMAT_RGB;
    std::vector<uint8_t> bytes(PNG_IMAGE_SIZE(png));
    ASSERT_TRUE(png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) << png.message;
    auto pixel = [&](int x, int y) {
        const uint8_t* p = &bytes[3 * (y * 4 + x)];
        return std::vector<int>{p[0], p[1], p[2]};
    };
    EXPECT_EQ(pixel(0, 0), (std::vector<int>{0, srgb8(0.5), 255}));
    EXPECT_EQ(pixel(1, 0), (std::vector<int>{srgb8(0.002), srgb8(0.2), 0}));
    EXPECT_EQ(pixel(2, 0), (std::vector<int>{255, srgb8(0.5), srgb8(0.125)}));
    EXPECT_EQ(pixel(3, 0), (std::vector<int>{255, 0, 255}));
    EXPECT_EQ(pixel(0, 1), (std::vector<int>{255, 0, 255}));
    EXPECT_EQ(pixel(1, 1), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(srgb8(0.5), 188);  // the formula itself, against a known value
}

TEST(Image, PreviewPath) {
    EXPECT_EQ(previewPath("out/x.exr"), "out/x.png");
    EXPECT_EQ(previewPath("render"), "render.png");
}

TEST(Image, DiffCommandJsonHasTheMeasurements) {
    const Pair p = handPair();
    const std::string a = test::tempDir() + "/a.exr", b = test::tempDir() + "/b.exr";
    writeExr(a, p.test);
    writeExr(b, p.reference);
    const auto r = test::runTetglow("diff " + a + " " + b + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j.at("rmse").get<double>(), kRmse, 1e-15);
    EXPECT_NEAR(j.at("rel_mse").get<double>(), kRelMse, 1e-13);
    EXPECT_NEAR(j.at("mae").get<double>(), kMae, 1e-15);
    EXPECT_EQ(j.at("max_error").get<double>(), 2.0);
    EXPECT_EQ(j.at("max_pixel"), nlohmann::json::array({1, 1}));
    EXPECT_EQ(j.at("non_finite").get<int>(), 2);
    EXPECT_EQ(j.at("width").get<int>(), 3);
    EXPECT_EQ(j.at("height").get<int>(), 2);

    const auto text = test::runTetglow("diff " + a + " " + b);
    EXPECT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("max_error   2 at pixel (1, 1)"), std::string::npos) << text.out;
}

// --tile: each tile's rel_mse, as compare() gives it for the tile cut out; a 3x2 image in tiles of
// 2 has a 2x2 tile and a 1x2 one, and the pixel-weighted mean of the tiles is the whole image's.
TEST(Image, DiffCommandTileErrorsAreTheTilesRelMse) {
    Image test(3, 2), reference(3, 2);
    for (int i = 0; i < 6; ++i) {
        test.pixels[i] = glm::vec3(0.1f * i, 1, 2);
        reference.pixels[i] = glm::vec3(0.05f * i, 1.5f, 2);
    }
    const std::string a = test::tempDir() + "/ta.exr", b = test::tempDir() + "/tb.exr";
    writeExr(a, test);
    writeExr(b, reference);
    const auto r = test::runTetglow("diff " + a + " " + b + " --json --tile 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto tiles = nlohmann::json::parse(r.out).at("tile_rel_mse").get<std::vector<double>>();
    ASSERT_EQ(tiles.size(), 2u);
    auto cut = [](const Image& image, int x0, int w) {
        Image c(w, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < w; ++x) c.at(x, y) = image.at(x0 + x, y);
        return c;
    };
    const Image a0 = readExr(a), b0 = readExr(b);
    EXPECT_DOUBLE_EQ(tiles[0], compare(cut(a0, 0, 2), cut(b0, 0, 2)).relMse);
    EXPECT_DOUBLE_EQ(tiles[1], compare(cut(a0, 2, 1), cut(b0, 2, 1)).relMse);
    EXPECT_NEAR((4 * tiles[0] + 2 * tiles[1]) / 6, compare(a0, b0).relMse, 1e-12);
    EXPECT_GT(tiles[1], tiles[0]);  // the error grows to the right
}

TEST(Image, DiffCommandBadInputExitsWithOne) {
    const std::string good = test::tempDir() + "/good.exr", missing = test::tempDir() + "/missing.exr";
    writeExr(good, Image(3, 2));
    const std::string corrupt = test::writeTemp("x.exr", "Dear diary,\ntoday I saw a fish.\n");
    const std::string small = test::tempDir() + "/small.exr";
    writeExr(small, Image(2, 2));
    for (const auto& [args, expected] :
         std::vector<std::pair<std::string, std::string>>{{missing + " " + good, missing},
                                                          {good + " " + missing, missing},
                                                          {corrupt + " " + good, corrupt},
                                                          {small + " " + good, "2x2"}}) {
        const auto r = test::runTetglow("diff " + args);
        EXPECT_EQ(r.exitCode, 1) << args << ": " << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    }
    EXPECT_EQ(test::runTetglow("diff " + good).exitCode, 2);
    EXPECT_EQ(test::runTetglow("diff " + good + " " + good + " --frobnicate").exitCode, 2);
}

}  // namespace
}  // namespace tetglow
