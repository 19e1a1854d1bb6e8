#include "scene/GltfVersion.h"

#include <cstdint>

#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace tetglow {
namespace {

using Json = nlohmann::json;

// Reads JSON only as far as the top level's "asset" "version" string, without building anything
// (a glTF's JSON may hold its buffers as data URIs); stops there.
class AssetVersion : public nlohmann::json_sax<Json> {
public:
    std::string version;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool string(string_t& value) override {
        if (depth_ != 2 || !inAsset_ || key_ != "version") return true;
        version = value;
        return false;
    }
    bool start_object(std::size_t) override {
        ++depth_;
        inAsset_ = depth_ == 2 && topKey_ == "asset";
        return true;
    }
    bool start_array(std::size_t) override {
        ++depth_;
        return true;
    }
    bool end_object() override {
        if (depth_-- == 2) inAsset_ = false;
        return true;
    }
    bool end_array() override {
        --depth_;
        return true;
    }
    bool key(string_t& key) override {
        if (depth_ == 1) topKey_ = key;
        if (depth_ == 2) key_ = key;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
    size_t depth_ = 0;
    bool inAsset_ = false;
    std::string topKey_, key_;
};

}  // namespace

void refuseGltf1(const std::string& data, const std::string& path, bool binary) {
    bool one = false;
    if (binary) {
        uint32_t version = 0;  // little-endian, after the magic "glTF"
        if (data.size() >= 8)
            for (int i = 3; i >= 0; --i) version = version << 8 | uint8_t(data[4 + size_t(i)]);
        one = version == 1;
    } else {
        AssetVersion sax;
        Json::sax_parse(data, &sax);  // a syntax error ends it: Assimp names the problem
        one = sax.version == "1" || sax.version.rfind("1.", 0) == 0;
    }
    if (one) throw InputError(path + ": glTF 1.0 is not supported; re-export as glTF 2.0");
}

}  // namespace tetglow
