#include "render/PartialRender.h"

#include <algorithm>
#include <bit>
#include <filesystem>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "base/Memory.h"
#include "base/OutputFile.h"
#include "render/ExrMemoryStream.h"
#include "render/ImageIO.h"
#include "tet/TriangleMesh.h"

namespace tetglow {
namespace {

// The sum words are sliced straight out of the 128-bit integers, least significant word first.
static_assert(std::endian::native == std::endian::little, "partial renders assume a little-endian machine");
static_assert(sizeof(FixedSum) == 3 * 16);

const char* const kRgb[3] = {"R", "G", "B"};

std::string passRange(const PartInfo& info) {
    return std::to_string(info.firstPass) + ":" + std::to_string(info.endPass);
}

std::string wordChannel(int c, int w) { return std::string("sum.") + kRgb[c] + "." + std::to_string(w); }

// Slices over the film's state (and the mean image for R, G, B): reading and writing go through them.
void insertFilmSlices(Imf::FrameBuffer& fb, Film& film, Image* mean, const Imath::Box2i& window) {
    const size_t row = size_t(film.width());
    for (int c = 0; c < 3; ++c) {
        if (mean)
            fb.insert(kRgb[c], Imf::Slice::Make(Imf::FLOAT, &mean->pixels[0][c], window, sizeof(glm::vec3),
                                                sizeof(glm::vec3) * row));
        for (int w = 0; w < 4; ++w)
            fb.insert(wordChannel(c, w), Imf::Slice::Make(Imf::UINT, reinterpret_cast<char*>(&film.sum(0)[c]) + 4 * w,
                                                          window, sizeof(FixedSum), sizeof(FixedSum) * row));
    }
    fb.insert("count", Imf::Slice::Make(Imf::UINT, &film.count(0), window, sizeof(uint32_t), sizeof(uint32_t) * row));
    fb.insert("dropped",
              Imf::Slice::Make(Imf::UINT, &film.dropped(0), window, sizeof(uint32_t), sizeof(uint32_t) * row));
}

template <class Attribute>
auto attribute(const std::string& path, const Imf::Header& header, const char* name) {
    const auto* a = header.findTypedAttribute<Attribute>(name);
    if (!a) throw InputError(path + ": not a partial render (tetglow render --pass-range): no " + name + " attribute");
    return a->value();
}

}  // namespace

void writePartial(const std::string& path, const PartialRender& part) {
    Film& film = const_cast<Film&>(part.film);  // OpenEXR's slices take non-const pointers; writing only reads them
    if (film.pixelCount() == 0) throw InputError(path + ": cannot write an empty image");
    Image mean = film.image();
    writeAtomically(path, [&](const std::string& temporary) {
        Imf::Header header(film.width(), film.height());
        for (const char* c : kRgb) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (int c = 0; c < 3; ++c)
            for (int w = 0; w < 4; ++w) header.channels().insert(wordChannel(c, w), Imf::Channel(Imf::UINT));
        header.channels().insert("count", Imf::Channel(Imf::UINT));
        header.channels().insert("dropped", Imf::Channel(Imf::UINT));
        header.insert("tetglowFingerprint", Imf::StringAttribute(part.info.fingerprint));
        header.insert("tetglowBuild", Imf::StringAttribute(part.info.build));
        header.insert("tetglowScene", Imf::StringAttribute(part.info.scene));
        header.insert("tetglowFirstPass", Imf::IntAttribute(part.info.firstPass));
        header.insert("tetglowEndPass", Imf::IntAttribute(part.info.endPass));
        header.insert("tetglowTotalPasses", Imf::IntAttribute(part.info.totalPasses));
        header.insert("tetglowFrame", Imf::IntAttribute(part.info.frame));
        Imf::FrameBuffer fb;
        insertFilmSlices(fb, film, &mean, header.dataWindow());
        Imf::OutputFile file(temporary.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(film.height());
    });
}

PartialRender readPartial(const std::string& path, double heldBytes) {
    const std::string data = readExrBytes(path, "a partial render");
    try {
        ExrMemoryStream stream(data, path);
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        PartialRender part;
        part.info.fingerprint = attribute<Imf::StringAttribute>(path, header, "tetglowFingerprint");
        part.info.build = attribute<Imf::StringAttribute>(path, header, "tetglowBuild");
        part.info.scene = attribute<Imf::StringAttribute>(path, header, "tetglowScene");
        part.info.firstPass = attribute<Imf::IntAttribute>(path, header, "tetglowFirstPass");
        part.info.endPass = attribute<Imf::IntAttribute>(path, header, "tetglowEndPass");
        part.info.totalPasses = attribute<Imf::IntAttribute>(path, header, "tetglowTotalPasses");
        part.info.frame = attribute<Imf::IntAttribute>(path, header, "tetglowFrame");
        if (part.info.firstPass < 0 || part.info.endPass <= part.info.firstPass ||
            part.info.endPass > part.info.totalPasses)
            throw InputError(path + ": passes " + passRange(part.info) + " are not a range of the render's " +
                             std::to_string(part.info.totalPasses));
        for (int c = 0; c < 3; ++c)
            for (int w = 0; w < 4; ++w)
                if (header.channels().findChannel(wordChannel(c, w)) == nullptr ||
                    header.channels().findChannel(wordChannel(c, w))->type != Imf::UINT)
                    throw InputError(path + ": not a partial render: no 32-bit integer channel " + wordChannel(c, w));
        for (const char* name : {"count", "dropped"})
            if (header.channels().findChannel(name) == nullptr ||
                header.channels().findChannel(name)->type != Imf::UINT)
                throw InputError(path + ": not a partial render: no 32-bit integer channel " + std::string(name));
        const Imath::Box2i window = header.dataWindow();
        const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        checkMemory(heldBytes + double(data.size()) + double(width) * height * kFilmBytesPerPixel,
                    path + ": a " + std::to_string(width) + "x" + std::to_string(height) + " part");
        part.film = Film(width, height);
        Imf::FrameBuffer fb;
        insertFilmSlices(fb, part.film, nullptr, window);
        file.setFrameBuffer(fb);
        file.readPixels(window.min.y, window.max.y);
        return part;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        throw InputError(path + ": cannot read: " + message);
    }
}

PartialRender mergeParts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw InputError("merge: no parts given");
    // One part at a time is read and added to the sum (exact in any order): the memory is one
    // film and one part, however many parts there are.
    PartialRender whole = readPartial(paths.front());
    const PartInfo first = whole.info;
    struct Read {
        std::string path;
        PartInfo info;
    };
    std::vector<Read> read{{paths.front(), first}};
    for (size_t i = 1; i < paths.size(); ++i) {
        const std::string& path = paths[i];
        const PartialRender part = readPartial(path, double(whole.film.pixelCount()) * kFilmBytesPerPixel);
        const PartInfo& b = part.info;
        if (b.build != first.build)
            throw InputError(path + ": made by another tetglow build than " + paths.front() + " (build " + b.build +
                             " vs " + first.build + "): render every part with one binary");
        if (b.fingerprint != first.fingerprint || b.totalPasses != first.totalPasses)
            throw InputError(path + ": a different scene or different settings from " + paths.front() + " (" + b.scene +
                             " vs " + first.scene + ", fingerprint " + b.fingerprint + " vs " + first.fingerprint +
                             ")");
        if (b.frame != first.frame)
            throw InputError(path + ": frame " + std::to_string(b.frame) + ", but " + paths.front() + " is frame " +
                             std::to_string(first.frame));
        if (!whole.film.merge(part.film))
            throw InputError(path + ": " + std::to_string(part.film.width()) + "x" +
                             std::to_string(part.film.height()) + " pixels, but " + paths.front() + " has " +
                             std::to_string(whole.film.width()) + "x" + std::to_string(whole.film.height()));
        read.push_back({path, b});
    }
    std::stable_sort(read.begin(), read.end(),
                     [](const Read& a, const Read& b) { return a.info.firstPass < b.info.firstPass; });
    int covered = 0;  // passes 0 .. covered - 1 are in the parts checked so far
    for (size_t i = 0; i < read.size(); ++i) {
        const PartInfo& info = read[i].info;
        if (info.firstPass < covered)
            throw InputError(read[i].path + ": passes " + passRange(info) + " overlap passes " +
                             passRange(read[i - 1].info) + " of " + read[i - 1].path);
        if (info.firstPass > covered)
            throw InputError(read[i].path + ": passes " + std::to_string(covered) + ":" +
                             std::to_string(info.firstPass) + " before its " + passRange(info) + " are in no part");
        covered = info.endPass;
    }
    const Read& last = read.back();
    if (covered < last.info.totalPasses)
        throw InputError(last.path + ": passes " + std::to_string(covered) + ":" +
                         std::to_string(last.info.totalPasses) + " after its " + passRange(last.info) +
                         " are in no part");
    whole.info.firstPass = 0;
    whole.info.endPass = whole.info.totalPasses;
    return whole;
}

}  // namespace tetglow
