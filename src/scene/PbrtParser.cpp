#include "scene/PbrtParser.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "base/ExternalReference.h"
#include "scene/PbrtOptions.h"
#include "scene/PbrtTokenizer.h"
#include "scene/PbrtTransform.h"
#include "scene/PbrtWorld.h"
#include "scene/SceneLoader.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;
constexpr size_t kMaxBlockDepth = 1024;  // AttributeBegin and TransformBegin blocks open at once

class Parser;
using Handler = void (Parser::*)(const PbrtToken&);

class Parser {
public:
    Parser(const std::string& path, std::vector<std::string>& warnings)
        : path_(path),
          tokens_(path),
          searchDir_(fs::path(path).parent_path()),
          warnings_(warnings),
          world_(searchDir_, warnings) {}

    SceneDesc run();
    static const std::map<std::string_view, Handler>& handlers();

private:
    enum class Block { Options, World, Done };
    struct Saved {
        bool attributes;  // AttributeBegin; else TransformBegin
        glm::dmat4 ctm;
        PbrtAttributes state;
        PbrtLocation where;
    };

    // Directive arguments.
    std::vector<double> numbers(const PbrtToken& d, int count, bool bracketed = false);
    std::string string(const PbrtToken& d);
    PbrtCall call(const PbrtToken& d);
    void require(Block block, const PbrtToken& d) const;

    void identity(const PbrtToken&) { ctm_ = glm::dmat4(1); }
    void translate(const PbrtToken& d);
    void scale(const PbrtToken& d);
    void rotate(const PbrtToken& d);
    void lookAt(const PbrtToken& d);
    void transform(const PbrtToken& d);
    void concatTransform(const PbrtToken& d);
    void coordinateSystem(const PbrtToken& d) { coordinateSystems_[string(d)] = ctm_; }
    void coordSysTransform(const PbrtToken& d);
    void activeTransform(const PbrtToken& d);
    void transformTimes(const PbrtToken& d);
    void camera(const PbrtToken& d);
    void option(const PbrtToken& d);
    void worldBegin(const PbrtToken& d);
    void worldEnd(const PbrtToken& d);
    void begin(const PbrtToken& d);
    void end(const PbrtToken& d);
    void makeNamedMedium(const PbrtToken& d);
    void mediumInterface(const PbrtToken& d);
    void material(const PbrtToken& d);
    void makeNamedMaterial(const PbrtToken& d);
    void namedMaterial(const PbrtToken& d);
    void lightSource(const PbrtToken& d);
    void areaLightSource(const PbrtToken& d);
    void shape(const PbrtToken& d);
    void reverseOrientation(const PbrtToken& d);
    void include(const PbrtToken& d);
    void unsupported(const PbrtToken& d);

    std::string path_;
    PbrtTokenizer tokens_;
    fs::path searchDir_;  // pbrt-v3 resolves every file name against the first file's folder
    std::vector<std::string>& warnings_;
    Block block_ = Block::Options;
    glm::dmat4 ctm_{1};
    PbrtAttributes attributes_;
    std::vector<Saved> stack_;
    std::map<std::string, glm::dmat4> coordinateSystems_;
    PbrtOptions options_;
    PbrtWorld world_;
    PbrtLocation last_{path_, 1};
};

const std::map<std::string_view, Handler>& Parser::handlers() {
    static const std::map<std::string_view, Handler> table = {
        {"Identity", &Parser::identity},
        {"Translate", &Parser::translate},
        {"Scale", &Parser::scale},
        {"Rotate", &Parser::rotate},
        {"LookAt", &Parser::lookAt},
        {"Transform", &Parser::transform},
        {"ConcatTransform", &Parser::concatTransform},
        {"CoordinateSystem", &Parser::coordinateSystem},
        {"CoordSysTransform", &Parser::coordSysTransform},
        {"ActiveTransform", &Parser::activeTransform},
        {"TransformTimes", &Parser::transformTimes},
        {"Camera", &Parser::camera},
        {"Film", &Parser::option},
        {"Sampler", &Parser::option},
        {"Integrator", &Parser::option},
        {"PixelFilter", &Parser::option},
        {"Accelerator", &Parser::option},
        {"WorldBegin", &Parser::worldBegin},
        {"WorldEnd", &Parser::worldEnd},
        {"AttributeBegin", &Parser::begin},
        {"TransformBegin", &Parser::begin},
        {"AttributeEnd", &Parser::end},
        {"TransformEnd", &Parser::end},
        {"MakeNamedMedium", &Parser::makeNamedMedium},
        {"MediumInterface", &Parser::mediumInterface},
        {"Material", &Parser::material},
        {"MakeNamedMaterial", &Parser::makeNamedMaterial},
        {"NamedMaterial", &Parser::namedMaterial},
        {"LightSource", &Parser::lightSource},
        {"AreaLightSource", &Parser::areaLightSource},
        {"Shape", &Parser::shape},
        {"ReverseOrientation", &Parser::reverseOrientation},
        {"Include", &Parser::include},
        {"Texture", &Parser::unsupported},
        {"ObjectBegin", &Parser::unsupported},
        {"ObjectEnd", &Parser::unsupported},
        {"ObjectInstance", &Parser::unsupported},
    };
    return table;
}

SceneDesc Parser::run() {
    while (auto t = tokens_.next()) {
        last_ = t->where;
        const auto handler = handlers().find(t->text);
        if (t->kind != PbrtToken::Kind::Word || handler == handlers().end())
            pbrtError(t->where, t->kind == PbrtToken::Kind::Word ? "unknown directive \"" + t->text + "\""
                                                                 : "expected a directive, got '" + t->text + "'");
        if (block_ == Block::Done)
            pbrtError(t->where, t->text + " after WorldEnd: tetglow renders one WorldBegin/WorldEnd block per file");
        (this->*handler->second)(*t);
    }
    if (block_ != Block::Done)
        pbrtError(last_, block_ == Block::Options ? "the file has no WorldBegin" : "the file ends without WorldEnd");
    SceneDesc s;
    s.path = path_;
    s.lights = std::move(world_.lights);
    s.surfaces = std::move(world_.surfaces);
    s.nesting = world_.checkNesting();
    s.media = std::move(world_.media);
    applyPbrtOptions(options_, s, warnings_);
    if (!emitsLight(s)) pbrtError(last_, "nothing emits light (pbrt-v3 would render a black image)");
    return s;
}

std::vector<double> Parser::numbers(const PbrtToken& d, int count, bool bracketed) {
    const std::string expected =
        d.text + " expects " + (bracketed ? "[" : "") + std::to_string(count) + " numbers" + (bracketed ? "]" : "");
    auto next = [&](PbrtToken::Kind kind) {
        auto t = tokens_.next();
        if (!t || t->kind != kind) pbrtError(d.where, expected + (t ? ", got '" + t->text + "'" : ""));
        return *t;
    };
    if (bracketed) next(PbrtToken::Kind::Open);
    std::vector<double> values;
    for (int i = 0; i < count; ++i) {
        const PbrtToken t = next(PbrtToken::Kind::Word);
        char* end = nullptr;
        values.push_back(std::strtod(t.text.c_str(), &end));
        if (*end != '\0' || !std::isfinite(values.back())) pbrtError(d.where, expected + ", got '" + t.text + "'");
    }
    if (bracketed) next(PbrtToken::Kind::Close);
    return values;
}

std::string Parser::string(const PbrtToken& d) {
    auto t = tokens_.next();
    if (!t || t->kind != PbrtToken::Kind::String) pbrtError(d.where, d.text + " expects a quoted string");
    return t->text;
}

PbrtCall Parser::call(const PbrtToken& d) {
    PbrtCall c;
    c.type = string(d);
    c.where = d.where;
    c.params = PbrtParams(tokens_, d.text + " \"" + c.type + "\"");
    return c;
}

void Parser::require(Block block, const PbrtToken& d) const {
    if (block_ == block) return;
    pbrtError(d.where, d.text + (block == Block::World ? " is only allowed between WorldBegin and WorldEnd"
                                                       : " is only allowed before WorldBegin"));
}

void Parser::translate(const PbrtToken& d) {
    const auto v = numbers(d, 3);
    ctm_ = glm::translate(ctm_, glm::dvec3(v[0], v[1], v[2]));
}

void Parser::scale(const PbrtToken& d) {
    const auto v = numbers(d, 3);
    ctm_ = glm::scale(ctm_, glm::dvec3(v[0], v[1], v[2]));
}

void Parser::rotate(const PbrtToken& d) {
    const auto v = numbers(d, 4);
    const glm::dvec3 axis(v[1], v[2], v[3]);
    if (axis == glm::dvec3(0)) pbrtError(d.where, "Rotate: the axis must not be zero");
    ctm_ = glm::rotate(ctm_, glm::radians(v[0]), axis);  // pbrt-v3's Rotate: right-handed about the unit axis
}

void Parser::lookAt(const PbrtToken& d) {
    const auto v = numbers(d, 9);
    glm::dmat4 m;
    if (!pbrtLookAt({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, m))
        pbrtError(d.where, "LookAt: the up vector must not be zero or parallel to the view direction");
    ctm_ = ctm_ * m;
}

// pbrt-v3 reads the 16 numbers column by column (translation in 12, 13, 14), as glm stores them.
void Parser::transform(const PbrtToken& d) { ctm_ = glm::make_mat4(numbers(d, 16, true).data()); }

void Parser::concatTransform(const PbrtToken& d) { ctm_ = ctm_ * glm::make_mat4(numbers(d, 16, true).data()); }

void Parser::coordSysTransform(const PbrtToken& d) {
    const std::string name = string(d);
    const auto it = coordinateSystems_.find(name);
    if (it == coordinateSystems_.end()) pbrtError(d.where, "CoordSysTransform: no coordinate system \"" + name + "\"");
    ctm_ = it->second;
}

void Parser::activeTransform(const PbrtToken& d) {
    const auto t = tokens_.next();
    if (!t || t->kind != PbrtToken::Kind::Word || (t->text != "All" && t->text != "StartTime" && t->text != "EndTime"))
        pbrtError(d.where, "ActiveTransform expects All, StartTime or EndTime");
    if (t->text != "All") pbrtError(d.where, "ActiveTransform " + t->text + ": motion blur is not supported");
}

void Parser::transformTimes(const PbrtToken& d) {
    require(Block::Options, d);
    numbers(d, 2);  // times matter only to animated transforms
}

void Parser::camera(const PbrtToken& d) {
    require(Block::Options, d);
    options_.camera = call(d);
    if (!attributes_.outsideMedium.empty())
        pbrtError(d.where, "Camera: a camera inside medium \"" + attributes_.outsideMedium + "\" is not supported");
    if (!(std::abs(glm::determinant(ctm_)) > 0)) pbrtError(d.where, "Camera: the transform is singular");
    options_.cameraToWorld = glm::inverse(ctm_);
    coordinateSystems_["camera"] = options_.cameraToWorld;
}

void Parser::option(const PbrtToken& d) {
    require(Block::Options, d);
    PbrtCall c = call(d);
    if (d.text == "Film")
        options_.film = std::move(c);
    else if (d.text == "Sampler")
        options_.sampler = std::move(c);
    else if (d.text == "Integrator")
        options_.integrator = std::move(c);
    else if (d.text == "PixelFilter")
        options_.filter = std::move(c);
    // Accelerator: how pbrt-v3 finds hits, not what it finds
}

void Parser::worldBegin(const PbrtToken& d) {
    require(Block::Options, d);
    block_ = Block::World;
    ctm_ = glm::dmat4(1);
    coordinateSystems_["world"] = ctm_;
    options_.worldBegin = d.where;
}

void Parser::worldEnd(const PbrtToken& d) {
    require(Block::World, d);
    for (auto it = stack_.rbegin(); it != stack_.rend(); ++it)
        pbrtWarn(warnings_, it->where,
                 std::string(it->attributes ? "AttributeBegin" : "TransformBegin") + " without an end before WorldEnd");
    block_ = Block::Done;
}

void Parser::begin(const PbrtToken& d) {
    require(Block::World, d);
    // Each level keeps a copy of the graphics state: a file of nothing but AttributeBegin took
    // 1.4 GB for 2 million of them. Real scenes nest a few dozen deep.
    if (stack_.size() >= kMaxBlockDepth)
        pbrtError(d.where, d.text + " nested more than " + std::to_string(kMaxBlockDepth) +
                               " deep (AttributeBegin and TransformBegin together)");
    stack_.push_back({d.text == "AttributeBegin", ctm_, attributes_, d.where});
}

void Parser::end(const PbrtToken& d) {
    require(Block::World, d);
    const bool attributes = d.text == "AttributeEnd";
    const char* opener = attributes ? "AttributeBegin" : "TransformBegin";
    if (stack_.empty()) pbrtError(d.where, d.text + " without " + opener);
    if (stack_.back().attributes != attributes)
        pbrtError(d.where, d.text + " closes the " + (attributes ? "TransformBegin" : "AttributeBegin") + " at " +
                               stack_.back().where.str());
    ctm_ = stack_.back().ctm;
    if (attributes) attributes_ = std::move(stack_.back().state);
    stack_.pop_back();
}

void Parser::makeNamedMedium(const PbrtToken& d) {
    PbrtCall c = call(d);
    world_.namedMedium(c);
}

void Parser::mediumInterface(const PbrtToken& d) {
    attributes_.insideMedium = string(d);
    // pbrt-v3: one name is both sides; a second quoted string is the outside.
    auto second = tokens_.next();
    if (second && second->kind == PbrtToken::Kind::String) {
        attributes_.outsideMedium = second->text;
    } else {
        attributes_.outsideMedium = attributes_.insideMedium;
        if (second) tokens_.unget(std::move(*second));
    }
}

void Parser::material(const PbrtToken& d) {
    require(Block::World, d);
    PbrtCall c = call(d);
    world_.checkMaterial(c);
    attributes_.material = std::move(c);
    attributes_.namedMaterial.clear();
}

void Parser::makeNamedMaterial(const PbrtToken& d) {
    require(Block::World, d);
    PbrtCall c = call(d);
    attributes_.namedMaterials[c.type] = world_.namedMaterial(c);
}

void Parser::namedMaterial(const PbrtToken& d) {
    require(Block::World, d);
    attributes_.namedMaterial = string(d);
}

void Parser::lightSource(const PbrtToken& d) {
    require(Block::World, d);
    PbrtCall c = call(d);
    world_.lightSource(c, ctm_);
}

void Parser::areaLightSource(const PbrtToken& d) {
    require(Block::World, d);
    PbrtCall c = call(d);
    attributes_.areaLight = world_.areaLightSource(c);
}

void Parser::shape(const PbrtToken& d) {
    require(Block::World, d);
    PbrtCall c = call(d);
    world_.shape(c, ctm_, attributes_);
}

void Parser::reverseOrientation(const PbrtToken& d) {
    require(Block::World, d);
    attributes_.reverseOrientation = !attributes_.reverseOrientation;
}

// Relative to the including file's folder. pbrt-v3 itself resolves every name against the first
// file's folder: the same for includes from the first file; otherwise that file is the fallback,
// and a warning says so where both exist.
// Either way, the file must lie in the first file's folder (base/ExternalReference.h).
void Parser::include(const PbrtToken& d) {
    const fs::path file = string(d);
    const auto read = [&](const fs::path& path) {
        try {
            checkReference(path, file.string(), searchDir_);
        } catch (const InputError& e) {
            pbrtError(d.where, std::string("Include: ") + e.what());
        }
        tokens_.include(path.string(), d.where);
    };
    if (file.is_absolute()) return read(file);
    const fs::path beside = fs::path(d.where.file).parent_path() / file, pbrtV3 = searchDir_ / file;
    std::error_code ec;
    const bool besideExists = fs::exists(beside, ec), pbrtV3Exists = fs::exists(pbrtV3, ec);
    if (besideExists && pbrtV3Exists && !fs::equivalent(beside, pbrtV3, ec))
        pbrtWarn(warnings_, d.where, "Include reads " + beside.string() + "; pbrt-v3 would read " + pbrtV3.string());
    read(besideExists || !pbrtV3Exists ? beside : pbrtV3);
}

void Parser::unsupported(const PbrtToken& d) { pbrtError(d.where, d.text + " is not supported"); }

}  // namespace

SceneDesc loadPbrtScene(const std::string& path, std::vector<std::string>* warnings) {
    if (warnings) return Parser(path, *warnings).run();
    std::vector<std::string> own;
    // The warnings before an error still help, so they are printed either way.
    auto print = [&] {
        for (const auto& w : own) std::cerr << w << '\n';
    };
    try {
        SceneDesc scene = Parser(path, own).run();
        print();
        return scene;
    } catch (...) {
        print();
        throw;
    }
}

bool looksLikePbrt(const std::string& text) {
    size_t i = 0;
    while (i < text.size()) {
        if (std::isspace((unsigned char)text[i]))
            ++i;
        else if (text[i] == '#')
            i = std::min(text.find('\n', i), text.size());
        else
            break;
    }
    size_t end = i;
    while (end < text.size() && std::isalpha((unsigned char)text[end])) ++end;
    return Parser::handlers().count(std::string_view(text).substr(i, end - i)) > 0;
}

}  // namespace tetglow
