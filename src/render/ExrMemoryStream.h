// OpenEXR files read with the bounds of every reader: the bytes come from readInputFile (a regular
// file within kMaxImageFileBytes), and OpenEXR's own header limits are set before it sizes its
// tables by a header's claims. Used by readExr (diff) and the partial renders (merge).
#pragma once
#include <cstdint>
#include <cstring>
#include <string>

#include <OpenEXR/IexBaseExc.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfVersion.h>

#include "base/InputFile.h"
#include "scene/SceneDescription.h"  // kMaxResolution
#include "tet/TriangleMesh.h"

namespace tetglow {

// An OpenEXR stream over bytes already read with readInputFile's checks and limit.
class ExrMemoryStream : public Imf::IStream {
public:
    ExrMemoryStream(const std::string& data, const std::string& name) : Imf::IStream(name.c_str()), data_(data) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos_ > data_.size() || uint64_t(n) > data_.size() - pos_)
            throw Iex::InputExc("unexpected end of file");
        std::memcpy(c, data_.data() + pos_, size_t(n));
        pos_ += uint64_t(n);
        return pos_ < data_.size();
    }
    uint64_t tellg() override { return pos_; }
    void seekg(uint64_t pos) override { pos_ = pos; }

private:
    const std::string& data_;
    uint64_t pos_ = 0;
};

// The bytes of the OpenEXR file at `path` (`what` names it in the size message), with OpenEXR's
// header limits in force; InputError if it is not an OpenEXR file.
inline std::string readExrBytes(const std::string& path, const char* what) {
    static const bool limited = [] {  // once, before the first header is read
        Imf::Header::setMaxImageSize(kMaxResolution, kMaxResolution);
        Imf::Header::setMaxTileSize(kMaxResolution, kMaxResolution);
        return true;
    }();
    (void)limited;
    std::string data = readInputFile(path, kMaxImageFileBytes, what);
    if (data.size() < 4 || !Imf::isImfMagic(data.data())) throw InputError(path + ": not an OpenEXR file");
    return data;
}

}  // namespace tetglow
