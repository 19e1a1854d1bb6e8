#include "render/ImageIO.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <png.h>

#include "base/InputFile.h"
#include "base/OutputFile.h"
#include "render/ExrMemoryStream.h"
#include "scene/SceneDescription.h"  // kMaxResolution
#include "tet/TriangleMesh.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

// The channel names of a layer: R, G, B for the default layer, else name.R, name.G, name.B.
std::array<std::string, 3> channelNames(const std::string& layer) {
    const std::string prefix = layer.empty() ? "" : layer + ".";
    return {prefix + "R", prefix + "G", prefix + "B"};
}

// Float slices over the pixels of `image`, which covers the data window. Reading writes through them.
void insertSlices(Imf::FrameBuffer& frameBuffer, const std::string& layer, const Image& image,
                  const Imath::Box2i& dataWindow) {
    const auto names = channelNames(layer);
    for (int c = 0; c < 3; ++c)
        frameBuffer.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &image.pixels[0][c], dataWindow, sizeof(glm::vec3),
                                                      sizeof(glm::vec3) * image.width));
}

void checkChannels(const std::string& path, const Imf::ChannelList& channels, const std::string& layer) {
    std::string missing, present;
    for (const auto& name : channelNames(layer))
        if (!channels.findChannel(name)) missing += (missing.empty() ? "" : ", ") + name;
    if (missing.empty()) return;
    for (auto it = channels.begin(); it != channels.end(); ++it)
        present += (present.empty() ? "" : ", ") + std::string(it.name());
    throw InputError(path + ": missing channels " + missing + " (the file has " +
                     (present.empty() ? std::string("none") : present) + ")");
}

// Linear to 8-bit sRGB (the sRGB OETF), v in [0, 1].
uint8_t encodeSrgb(double v) {
    const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return static_cast<uint8_t>(std::lround(255 * e));
}

// See writePng in the header for the choice of tonemap.
std::array<uint8_t, 3> previewPixel(const glm::vec3& linear, double scale) {
    if (!(std::isfinite(linear.x) && std::isfinite(linear.y) && std::isfinite(linear.z))) return {255, 0, 255};
    std::array<double, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = std::max(0.0, scale * linear[k]);
    const double largest = std::max({c[0], c[1], c[2], 1.0});
    return {encodeSrgb(c[0] / largest), encodeSrgb(c[1] / largest), encodeSrgb(c[2] / largest)};
}

}  // namespace

namespace {

void checkLayers(const std::string& path, const Image& rgb, const std::vector<ImageLayer>& layers) {
    if (rgb.pixels.empty()) throw InputError(path + ": cannot write an empty image");
    for (const auto& layer : layers)
        if (layer.image->width != rgb.width || layer.image->height != rgb.height)
            throw InputError(path + ": layer " + layer.name + " is not the size of the image");
}

// The EXR of writeExr straight into `file`.
void writeExrFile(const std::string& file, const Image& rgb, const std::vector<ImageLayer>& layers) {
    Imf::Header header(rgb.width, rgb.height);
    Imf::FrameBuffer frameBuffer;
    auto add = [&](const std::string& layer, const Image& image) {
        for (const auto& name : channelNames(layer)) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        insertSlices(frameBuffer, layer, image, header.dataWindow());
    };
    add("", rgb);
    for (const auto& layer : layers) add(layer.name, *layer.image);
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frameBuffer);
    out.writePixels(rgb.height);
}

void writePngFile(const std::string& file, const Image& rgb, double exposure) {
    const std::vector<uint8_t> png = encodePng(rgb, exposure);
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    if (!out.flush()) throw std::runtime_error("write failed");
}

}  // namespace

void writeExr(const std::string& path, const Image& rgb, const std::vector<ImageLayer>& layers) {
    checkLayers(path, rgb, layers);
    writeAtomically(path, [&](const std::string& temporary) { writeExrFile(temporary, rgb, layers); });
}

void writeExrAndPng(const std::string& exrPath, const Image& rgb, double exposure) {
    checkLayers(exrPath, rgb, {});
    writeTogether(
        {{exrPath, [&](const std::string& temporary) { writeExrFile(temporary, rgb, {}); }},
         {previewPath(exrPath), [&](const std::string& temporary) { writePngFile(temporary, rgb, exposure); }}});
}

Image readExr(const std::string& path, const std::string& layer) {
    const std::string data = readExrBytes(path, "an OpenEXR image");
    try {
        ExrMemoryStream stream(data, path);
        Imf::InputFile file(stream);
        checkChannels(path, file.header().channels(), layer);
        const Imath::Box2i dataWindow = file.header().dataWindow();
        const int64_t width = int64_t(dataWindow.max.x) - dataWindow.min.x + 1,
                      height = int64_t(dataWindow.max.y) - dataWindow.min.y + 1;
        if (width < 1 || height < 1 || width * height > kMaxExrPixels)
            throw InputError(path + ": the header claims " + std::to_string(width) + " x " + std::to_string(height) +
                             " pixels; at most " + std::to_string(kMaxExrPixels) + " pixels (and " +
                             std::to_string(kMaxResolution) + " per side) are read");
        Image image{int(width), int(height)};
        Imf::FrameBuffer frameBuffer;
        insertSlices(frameBuffer, layer, image, dataWindow);
        file.setFrameBuffer(frameBuffer);
        file.readPixels(dataWindow.min.y, dataWindow.max.y);
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read: " + oneLine(e.what()));
    }
}

std::vector<uint8_t> encodePng(const Image& rgb, double exposure) {
    const double scale = std::exp2(exposure);
    std::vector<uint8_t> bytes;
    bytes.reserve(3 * rgb.pixels.size());
    for (const auto& p : rgb.pixels)
        for (uint8_t b : previewPixel(p, scale)) bytes.push_back(b);
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = rgb.width;
    image.height = rgb.height;
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;  // asked for first, then written
    if (!png_image_write_get_memory_size(image, size, 0, bytes.data(), 0, nullptr))
        throw std::runtime_error(image.message);
    std::vector<uint8_t> png(size);
    if (!png_image_write_to_memory(&image, png.data(), &size, 0, bytes.data(), 0, nullptr))
        throw std::runtime_error(image.message);
    png.resize(size);
    return png;
}

void writePng(const std::string& path, const Image& rgb, double exposure) {
    writeAtomically(path, [&](const std::string& temporary) { writePngFile(temporary, rgb, exposure); });
}

std::string previewPath(const std::string& exrPath) { return fs::path(exrPath).replace_extension(".png").string(); }

}  // namespace tetglow
