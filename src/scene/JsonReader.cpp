#include "scene/JsonReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "base/Spelling.h"

namespace tetglow {
namespace {

using Json = nlohmann::json;
using Pointer = Json::json_pointer;

// A pass over the text before the real parse, only to place the first problem: nlohmann's errors
// carry no JSON pointer, its number overflow error no position, and it keeps the last of two
// duplicate keys without a word.
class SyntaxCheck : public nlohmann::json_sax<Json> {
public:
    SyntaxCheck(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        Level& level = levels_.back();
        level.key = key;
        if (!level.keys.insert(key).second) throw InputError(file_ + ": " + pointer().to_string() + ": duplicate key");
        return true;
    }

    bool parse_error(std::size_t offset, const std::string&, const nlohmann::detail::exception& e) override {
        const std::string path = pointer().to_string();
        throw InputError(file_ + ":" + lineAndColumn(offset) + ": " + (path.empty() ? "" : path + ": ") + reason(e));
    }

private:
    // An open object or array; `key` and `index` name the value being read in it.
    struct Level {
        bool array = false;
        size_t index = 0;
        std::optional<std::string> key;
        std::set<std::string> keys;
    };

    bool open(bool array) {
        // Printing a value in an error message recurses once per level: a bound keeps the stack safe.
        if (levels_.size() >= kMaxJsonDepth)
            throw InputError(file_ + ": " + pointer().to_string() + ": nested deeper than " +
                             std::to_string(kMaxJsonDepth) + " arrays and objects");
        levels_.emplace_back().array = array;
        return true;
    }
    bool close() {
        levels_.pop_back();
        return value();
    }
    // A value is complete: the next one in an array has the next index; in an object, a key.
    bool value() {
        if (levels_.empty()) return true;
        Level& level = levels_.back();
        if (level.array)
            ++level.index;
        else
            level.key.reset();
        return true;
    }

    Pointer pointer() const {
        Pointer p;
        for (const Level& level : levels_) {
            if (level.array)
                p /= level.index;
            else if (level.key)
                p /= *level.key;
            else
                break;
        }
        return p;
    }

    // `offset` counts the characters read, the offending one (or the end of the text) the last.
    std::string lineAndColumn(size_t offset) const {
        const size_t at = std::min(offset > 0 ? offset - 1 : 0, text_.size());
        const size_t newline = at > 0 ? text_.rfind('\n', at - 1) : std::string::npos;
        const size_t column = newline == std::string::npos ? at + 1 : at - newline;
        const auto line = 1 + std::count(text_.begin(), text_.begin() + at, '\n');
        return std::to_string(line) + ":" + std::to_string(column);
    }

    // nlohmann's message without its "[json.exception...] " tag and its own "parse error at line..".
    static std::string reason(const nlohmann::detail::exception& e) {
        std::string s = e.what();
        if (const size_t tag = s.find("] "); tag != std::string::npos) s.erase(0, tag + 2);
        if (s.rfind("parse error", 0) == 0)
            if (const size_t colon = s.find(": "); colon != std::string::npos) s.erase(0, colon + 2);
        return s;
    }

    const std::string& text_;
    const std::string& file_;
    std::vector<Level> levels_;
};

// Plain and short: 1e12, 3.40282e38, 0.5.
std::string formatNumber(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    std::string s = buf;
    if (const size_t e = s.find("e+"); e != std::string::npos) s.erase(e + 1, 1);
    if (const size_t e = s.find_first_of('e'); e != std::string::npos && s[e + 1 + (s[e + 1] == '-')] == '0')
        s.erase(e + 1 + (s[e + 1] == '-'), 1);
    return s;
}

// The offending value as JSON, cut short so that the error stays one readable line.
std::string shortDump(const Json& json) {
    constexpr size_t kMax = 60;
    std::string s = json.dump();
    return s.size() <= kMax ? s : s.substr(0, kMax) + "...";
}

bool isArrayOfNumbers(const Json* json, size_t count, const Range& range) {
    return json && json->is_array() && json->size() == count &&
           std::all_of(json->begin(), json->end(),
                       [&](const Json& x) { return x.is_number() && range.contains(x.get<double>()); });
}

}  // namespace

Json parseJson(const std::string& text, const std::string& file) {
    SyntaxCheck check(text, file);
    Json::sax_parse(text, &check);
    return Json::parse(text);
}

bool Range::contains(double x) const {
    return std::isfinite(x) && (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi);
}

std::string Range::describe(bool plural) const {
    const std::string noun = plural ? "numbers" : "number";
    if (std::isinf(hi)) {
        if (std::isinf(lo)) return "finite " + noun;
        if (lo == 0) return (loOpen ? "finite positive " : "finite non-negative ") + noun;
        return "finite " + noun + (loOpen ? " > " : " >= ") + formatNumber(lo);
    }
    return noun + " in " + (loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) + (hiOpen ? ")" : "]");
}

JsonValue::JsonValue(const Json* json, Pointer pointer, std::string file)
    : json_(json), pointer_(std::move(pointer)), file_(std::move(file)) {}

JsonValue JsonValue::child(const Json* json, const Pointer& pointer) const { return {json, pointer, file_}; }

std::string JsonValue::where() const {
    const std::string p = shorten(path(), 120);  // a 100 kB key stays readable
    return p.empty() ? file_ : file_ + ": " + p;
}

void JsonValue::error(const std::string& message) const { throw InputError(where() + ": " + message); }

void JsonValue::fail(const std::string& expected) const {
    if (!json_)
        error("missing; expected " + expected +
              (misspelling_.empty() ? ""
                                    : "; did you mean \"" + pointer_.back() + "\" where the file says \"" +
                                          shorten(misspelling_) + "\"?"));
    error("expected " + expected + ", got " + shortDump(*json_));
}

double JsonValue::number(const Range& range) const {
    if (!json_ || !json_->is_number() || !range.contains(json_->get<double>())) fail("a " + range.describe());
    return json_->get<double>();
}

int64_t JsonValue::integer(int64_t lo, int64_t hi) const {
    // A large unsigned value is compared as unsigned, so that it cannot wrap into the range.
    const bool ok = json_ && json_->is_number_integer() &&
                    (json_->is_number_unsigned() ? json_->get<uint64_t>() <= uint64_t(std::max<int64_t>(hi, 0))
                                                 : json_->get<int64_t>() <= hi) &&
                    json_->get<int64_t>() >= lo;
    // The range in full even without an upper bound: 2^63 is >= 0 and still refused.
    if (!ok) fail("an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return json_->get<int64_t>();
}

bool JsonValue::boolean() const {
    if (!json_ || !json_->is_boolean()) fail("true or false");
    return json_->get<bool>();
}

std::string JsonValue::string() const {
    if (!json_ || !json_->is_string() || json_->get_ref<const std::string&>().empty()) fail("a non-empty string");
    return json_->get<std::string>();
}

std::vector<double> JsonValue::numbers(size_t count, const Range& range) const {
    if (!isArrayOfNumbers(json_, count, range))
        fail("an array of " + std::to_string(count) + " " + range.describe(true));
    return json_->get<std::vector<double>>();
}

glm::dvec3 JsonValue::vec3(const Range& range) const {
    const auto v = numbers(3, range);
    return {v[0], v[1], v[2]};
}

glm::dvec3 JsonValue::vec3OrScalar(const Range& range) const {
    if (json_ && json_->is_number() && range.contains(json_->get<double>())) return glm::dvec3(json_->get<double>());
    if (!isArrayOfNumbers(json_, 3, range)) fail("an array of 3 " + range.describe(true) + " (or one for all 3)");
    return vec3(range);
}

std::vector<JsonValue> JsonValue::array() const {
    if (!json_ || !json_->is_array()) fail("an array");
    std::vector<JsonValue> items;
    for (size_t i = 0; i < json_->size(); ++i) items.push_back(child(&(*json_)[i], pointer_ / i));
    return items;
}

size_t JsonValue::choiceIndex(const std::vector<std::string_view>& names) const {
    if (json_ && json_->is_string()) {
        const auto it = std::find(names.begin(), names.end(), json_->get_ref<const std::string&>());
        if (it != names.end()) return size_t(it - names.begin());
    }
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    if (json_ && json_->is_string())
        error("expected one of " + list + ", got " + shortDump(*json_) +
              didYouMean(json_->get_ref<const std::string&>(), names));
    fail("one of " + list);
}

JsonObject::JsonObject(const JsonValue& value) : value_(value) {
    if (!value.json_ || !value.json_->is_object()) value.fail("an object");
}

JsonValue JsonObject::operator[](const std::string& key) {
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.push_back(key);
    const auto it = value_.json_->find(key);
    JsonValue v = value_.child(it == value_.json_->end() ? nullptr : &*it, value_.pointer_ / key);
    if (!v) {
        // A key of the object not asked for yet may be this one misspelt ("intensty").
        std::vector<std::string_view> unasked;
        for (const auto& [k, item] : value_.json_->items())
            if (std::find(asked_.begin(), asked_.end(), k) == asked_.end()) unasked.push_back(k);
        v.misspelling_ = nearestName(key, unasked);
    }
    return v;
}

void JsonObject::rejectUnknownKeys() const {
    for (const auto& [key, item] : value_.json_->items()) {
        if (std::find(asked_.begin(), asked_.end(), key) != asked_.end()) continue;
        std::string allowed;
        for (const auto& k : asked_) allowed += (allowed.empty() ? "" : ", ") + k;
        value_.child(&item, value_.pointer_ / key)
            .error("unknown key" + didYouMean(key, {asked_.begin(), asked_.end()}) + "; allowed here: " + allowed);
    }
}

}  // namespace tetglow
