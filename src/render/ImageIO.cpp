#include "render/ImageIO.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfTestFile.h>
#include <png.h>

#include "tet/TriangleMesh.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

// Library messages can span lines; ours are one line.
std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
}

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
    for (auto it = channels.begin(); it != channels.end(); ++it) present += (present.empty() ? "" : ", ") + std::string(it.name());
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

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write) {
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(path + ": directory " + dir.string() + " does not exist");
    const fs::path temporary = path + "." + std::to_string(::getpid()) + ".tmp";
    try {
        write(temporary.string());
        fs::rename(temporary, target);
    } catch (const std::exception& e) {
        fs::remove(temporary, ec);
        throw InputError(path + ": cannot write: " + oneLine(e.what()));
    }
}

void writeExr(const std::string& path, const Image& rgb, const std::vector<ImageLayer>& layers) {
    if (rgb.pixels.empty()) throw InputError(path + ": cannot write an empty image");
    for (const auto& layer : layers)
        if (layer.image->width != rgb.width || layer.image->height != rgb.height)
            throw InputError(path + ": layer " + layer.name + " is not the size of the image");
    writeAtomically(path, [&](const std::string& temporary) {
        Imf::Header header(rgb.width, rgb.height);
        Imf::FrameBuffer frameBuffer;
        auto add = [&](const std::string& layer, const Image& image) {
            for (const auto& name : channelNames(layer)) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            insertSlices(frameBuffer, layer, image, header.dataWindow());
        };
        add("", rgb);
        for (const auto& layer : layers) add(layer.name, *layer.image);
        Imf::OutputFile file(temporary.c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(rgb.height);
    });
}

Image readExr(const std::string& path, const std::string& layer) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
    if (!Imf::isOpenExrFile(path.c_str())) throw InputError(path + ": not an OpenEXR file");
    try {
        Imf::InputFile file(path.c_str());
        checkChannels(path, file.header().channels(), layer);
        const Imath::Box2i dataWindow = file.header().dataWindow();
        Image image(dataWindow.max.x - dataWindow.min.x + 1, dataWindow.max.y - dataWindow.min.y + 1);
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

void writePng(const std::string& path, const Image& rgb, double exposure) {
    const double scale = std::exp2(exposure);
    std::vector<uint8_t> bytes;
    bytes.reserve(3 * rgb.pixels.size());
    for (const auto& p : rgb.pixels)
        for (uint8_t b : previewPixel(p, scale)) bytes.push_back(b);
    writeAtomically(path, [&](const std::string& temporary) {
        png_image image;
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
        image.width = rgb.width;
        image.height = rgb.height;
        image.format = PNG_FORMAT_RGB;
        if (!png_image_write_to_file(&image, temporary.c_str(), 0, bytes.data(), 0, nullptr))
            throw std::runtime_error(image.message);
    });
}

std::string previewPath(const std::string& exrPath) { return fs::path(exrPath).replace_extension(".png").string(); }

}  // namespace tetglow
