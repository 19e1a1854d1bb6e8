#include "scene/PlyReader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace tetglow {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
    std::string name;
    Type type = Type::Float32;
    bool list = false;
    Type countType = Type::UInt8;  // list: the type of the length
};

struct Element {
    std::string name;
    size_t count = 0;
    std::vector<Property> properties;
    int find(const std::string& property) const {
        for (size_t i = 0; i < properties.size(); ++i)
            if (properties[i].name == property) return int(i);
        return -1;
    }
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

Type typeOf(const std::string& name, const std::string& path) {
    static const std::pair<const char*, Type> kTypes[] = {
        {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
        {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
        {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},    {"uint32", Type::UInt32},
        {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
    for (const auto& [n, t] : kTypes)
        if (name == n) return t;
    throw InputError(path + ": PLY header: unknown property type '" + name + "'");
}

size_t sizeOf(Type t) {
    switch (t) {
        case Type::Int8:
        case Type::UInt8: return 1;
        case Type::Int16:
        case Type::UInt16: return 2;
        case Type::Int32:
        case Type::UInt32:
        case Type::Float32: return 4;
        case Type::Float64: return 8;
    }
    return 0;
}

// The values after the header, read one at a time in the file's format.
class Body {
public:
    Body(const std::string& data, size_t start, Format format, const std::string& path)
        : data_(data), pos_(start), format_(format), path_(path) {}

    double read(Type t, const std::string& element) {
        if (format_ == Format::Ascii) return readAscii(element);
        const size_t n = sizeOf(t);
        if (pos_ + n > data_.size()) throw InputError(path_ + ": ends early, in element '" + element + "'");
        unsigned char b[8];
        std::memcpy(b, data_.data() + pos_, n);
        pos_ += n;
        const bool little = std::endian::native == std::endian::little;
        if ((format_ == Format::BinaryLittle) != little)
            for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        return decode(t, b);
    }

private:
    static double decode(Type t, const unsigned char* b) {
        switch (t) {
            case Type::Int8: return double(int8_t(b[0]));
            case Type::UInt8: return double(b[0]);
            case Type::Int16: return double(load<int16_t>(b));
            case Type::UInt16: return double(load<uint16_t>(b));
            case Type::Int32: return double(load<int32_t>(b));
            case Type::UInt32: return double(load<uint32_t>(b));
            case Type::Float32: return double(load<float>(b));
            case Type::Float64: return load<double>(b);
        }
        return 0;
    }
    template <class T>
    static T load(const unsigned char* b) {
        T x;
        std::memcpy(&x, b, sizeof x);
        return x;
    }

    double readAscii(const std::string& element) {
        while (pos_ < data_.size() && std::isspace((unsigned char)data_[pos_])) ++pos_;
        const size_t start = pos_;
        while (pos_ < data_.size() && !std::isspace((unsigned char)data_[pos_])) ++pos_;
        if (start == pos_) throw InputError(path_ + ": ends early, in element '" + element + "'");
        const std::string token = data_.substr(start, pos_ - start);
        char* end = nullptr;
        const double x = std::strtod(token.c_str(), &end);
        if (*end != '\0') throw InputError(path_ + ": '" + token + "' is not a number, in element '" + element + "'");
        return x;
    }

    const std::string& data_;
    size_t pos_;
    Format format_;
    const std::string& path_;
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t bodyStart = 0;
};

Header readHeader(const std::string& data, const std::string& path, std::vector<std::string>* warnings) {
    Header h;
    size_t pos = 0;
    bool sawFormat = false;
    for (int lineNo = 1;; ++lineNo) {
        const size_t eol = data.find('\n', pos);
        if (eol == std::string::npos) throw InputError(path + ": PLY header without 'end_header'");
        std::string line = data.substr(pos, eol - pos);
        pos = eol + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        auto bad = [&] {
            return InputError(path + ":" + std::to_string(lineNo) + ": PLY header: cannot read '" + line + "'");
        };
        if (lineNo == 1) {
            if (key != "ply") throw InputError(path + ": not a PLY file (it must start with 'ply')");
        } else if (key == "format") {
            std::string name;
            ls >> name;
            if (name == "ascii")
                h.format = Format::Ascii;
            else if (name == "binary_little_endian")
                h.format = Format::BinaryLittle;
            else if (name == "binary_big_endian")
                h.format = Format::BinaryBig;
            else
                throw bad();
            sawFormat = true;
        } else if (key == "element") {
            Element e;
            if (!(ls >> e.name >> e.count)) throw bad();
            // Faces index one vertex list: which of two would be a guess.
            if (e.name == "vertex" &&
                std::any_of(h.elements.begin(), h.elements.end(), [](const Element& o) { return o.name == "vertex"; }))
                throw InputError(path + ": a second 'vertex' element in the header (faces index one vertex list)");
            h.elements.push_back(e);
        } else if (key == "property") {
            if (h.elements.empty()) throw bad();
            Property p;
            std::string type;
            if (!(ls >> type)) throw bad();
            if (type == "list") {
                std::string countType, itemType;
                if (!(ls >> countType >> itemType >> p.name)) throw bad();
                p.list = true;
                p.countType = typeOf(countType, path);
                p.type = typeOf(itemType, path);
            } else {
                if (!(ls >> p.name)) throw bad();
                p.type = typeOf(type, path);
            }
            h.elements.back().properties.push_back(p);
        } else if (key == "end_header") {
            break;
        } else if (key != "comment" && key != "obj_info" && !key.empty() && warnings) {
            addWarning(*warnings, path + ":" + std::to_string(lineNo) + ": PLY header: skipped the line '" +
                                      shorten(line) + "' (not format, element, property or end_header)");
        }
    }
    if (!sawFormat) throw InputError(path + ": PLY header without a 'format' line");
    h.bodyStart = pos;
    return h;
}

// The vertex index `x` of face or strip `index`, checked against the vertex count.
uint32_t vertexIndex(double x, size_t vertexCount, const char* what, size_t index, const std::string& path) {
    if (!(x >= 0 && x < double(vertexCount))) {
        // Printed as read: an index like 3e32 has no integer type to go through.
        char value[32];
        std::snprintf(value, sizeof value, "%.6g", x);
        throw InputError(path + ": " + what + " " + std::to_string(index) + ": vertex index " + value +
                         " out of range (" + std::to_string(vertexCount) + " vertices)");
    }
    return uint32_t(x);
}

// A triangle strip (v0 v1 v2 v3 ...): (v0 v1 v2), (v2 v1 v3), (v2 v3 v4), ..., every other one
// reversed so that all share the first one's winding; -1 starts a new strip. Triangles with a
// repeated vertex only join strips and are dropped.
void addStrip(TriangleMesh& out, const std::vector<double>& strip, size_t vertexCount, size_t index,
              const std::string& path) {
    std::vector<uint32_t> run;
    for (size_t k = 0; k <= strip.size(); ++k) {
        if (k == strip.size() || strip[k] == -1) {
            for (size_t i = 0; i + 2 < run.size(); ++i) {
                std::array<uint32_t, 3> t{run[i], run[i + 1], run[i + 2]};
                if (i % 2) std::swap(t[0], t[1]);
                if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) out.triangles.push_back(t);
            }
            run.clear();
        } else {
            run.push_back(vertexIndex(strip[k], vertexCount, "strip", index, path));
        }
    }
}

// The bytes one element takes at the least: a binary value its size, an ASCII one a character.
size_t smallestElement(const Element& e, bool ascii) {
    size_t n = 0;
    for (const Property& p : e.properties) n += ascii ? 1 : sizeOf(p.list ? p.countType : p.type);
    return n;
}

}  // namespace

MeshFile parsePly(const std::string& data, const std::string& path, std::vector<std::string>* warnings) {
    const Header header = readHeader(data, path, warnings);
    Body body(data, header.bodyStart, header.format, path);
    MeshFile out;
    // Faces listed before the vertices, triangulated once the positions are read.
    std::vector<std::pair<std::vector<uint32_t>, size_t>> pending;
    size_t vertexCount = 0;
    for (const Element& e : header.elements)
        if (e.name == "vertex") vertexCount = e.count;
    for (const Element& e : header.elements) {
        const int x = e.find("x"), y = e.find("y"), z = e.find("z"), nx = e.find("nx"), ny = e.find("ny"),
                  nz = e.find("nz");
        const bool vertices = e.name == "vertex", withNormals = vertices && nx >= 0 && ny >= 0 && nz >= 0;
        if (vertices && (x < 0 || y < 0 || z < 0)) throw InputError(path + ": the vertex element has no x, y, z");
        int indices = e.find("vertex_indices");
        if (indices < 0) indices = e.find("vertex_index");
        const bool faces = e.name == "face", strips = e.name == "tristrips";
        if ((faces || strips) && (indices < 0 || !e.properties[size_t(indices)].list))
            throw InputError(path + ": the " + e.name + " element has no 'vertex_indices' list");
        // An element without properties takes no bytes: its count bounds nothing, so it is not
        // counted through; any other must fit in what is left of the file.
        const size_t smallest = smallestElement(e, header.format == Format::Ascii);
        if (smallest == 0) continue;
        if (e.count > data.size() / smallest) throw InputError(path + ": ends early, in element '" + e.name + "'");
        std::vector<double> values, list;
        std::vector<uint32_t> face;
        for (size_t i = 0; i < e.count; ++i) {
            values.assign(e.properties.size(), 0);
            for (size_t k = 0; k < e.properties.size(); ++k) {
                const Property& p = e.properties[k];
                if (!p.list) {
                    values[k] = body.read(p.type, e.name);
                    continue;
                }
                const double n = body.read(p.countType, e.name);
                // Each item takes at least a byte, so a count beyond the file's size is a lie (and a
                // float count may not even fit the integer it is converted to).
                if (!(n >= 0 && n == std::floor(n) && n <= double(data.size())))
                    throw InputError(path + ": bad list length in element '" + e.name + "'");
                const bool keep = (faces || strips) && int(k) == indices;  // other lists are read past
                if (keep) list.clear();
                for (size_t j = 0; j < size_t(n); ++j) {
                    const double item = body.read(p.type, e.name);
                    if (keep) list.push_back(item);
                }
            }
            if (vertices) {
                out.mesh.positions.emplace_back(values[size_t(x)], values[size_t(y)], values[size_t(z)]);
                if (withNormals) out.normals.emplace_back(values[size_t(nx)], values[size_t(ny)], values[size_t(nz)]);
            }
            if (faces) {
                face.clear();
                for (double v : list) face.push_back(vertexIndex(v, vertexCount, "face", i, path));
                if (out.mesh.positions.size() < vertexCount)
                    pending.push_back({face, i});
                else
                    addPolygon(out.mesh, face, path + ": face " + std::to_string(i) + ": ");
            }
            if (strips) addStrip(out.mesh, list, vertexCount, i, path);
        }
    }
    for (const auto& [polygon, i] : pending) addPolygon(out.mesh, polygon, path + ": face " + std::to_string(i) + ": ");
    if (out.mesh.triangles.empty())
        throw InputError(path + ": no triangles (a PLY mesh needs 'vertex' and 'face' or 'tristrips' elements)");
    return out;
}

}  // namespace tetglow
