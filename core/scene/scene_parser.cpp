// The typed values of a scene file, each checked where it stands and named by its JSON path in
// the one-line message when it breaks the contract.

#include "core/scene/scene_parser.h"

#include "core/number_format.h"
#include "core/scene/scene_resolve.h"

#include <cctype>
#include <cmath>

namespace lucerna {

using json::Type;
using json::Value;

namespace {

bool isPlainKey(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    for (unsigned char c : key)
        if (!(std::isalnum(c) || c == '_' || c == '-')) return false;
    return true;
}

}  // namespace

std::string SceneParser::member(const std::string& parent, const std::string& key) {
    if (!isPlainKey(key)) return (parent == kTopLevel ? std::string() : parent) + "[" + quote(key) + "]";
    return parent == kTopLevel ? key : parent + "." + key;
}

void SceneParser::fail(const std::string& place, const std::string& problem) const {
    throw SceneError(file_ + ": " + place + ": " + problem);
}

void SceneParser::expectType(const Value& v, Type type, const std::string& place) const {
    if (v.type != type)
        fail(place, std::string("expected ") + json::describe(type) + ", got " + json::describe(v.type));
}

void SceneParser::checkKeys(const Value& v, const std::string& place, std::initializer_list<std::string_view> allowed,
                            const std::string& what) const {
    expectType(v, Type::Object, place);
    for (const json::Member& m : v.object) {
        bool known = false;
        for (std::string_view k : allowed) known = known || m.key == k;
        if (known) continue;
        std::string list;
        for (std::string_view k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(member(place, m.key), "unknown key" + (what.empty() ? std::string() : " for " + what) +
                                       " (expected one of: " + list + ")");
    }
}

const Value& SceneParser::required(const Value& object, const std::string& place, const std::string& key) const {
    if (const Value* v = object.find(key)) return *v;
    fail(member(place, key), "required key is missing");
}

double SceneParser::number(const Value& v, const std::string& place) const {
    expectType(v, Type::Number, place);
    return v.number;
}

double SceneParser::integer(const Value& v, const std::string& place) const {
    const double x = number(v, place);
    if (x != std::floor(x)) fail(place, "expected an integer, got " + shortestNumber(x));
    return x;
}

double SceneParser::numberIn(const Value& v, const std::string& place, double lo, bool loOpen, double hi, bool hiOpen,
                             const std::string& unit) const {
    const double x = number(v, place);
    const bool ok = (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi);
    if (!ok)
        fail(place, "must be in " + std::string(loOpen ? "(" : "[") + shortestNumber(lo) + ", " + shortestNumber(hi) +
                        (hiOpen ? ")" : "]") + unit + ", got " + shortestNumber(x));
    return x;
}

std::string SceneParser::text(const Value& v, const std::string& place) const {
    expectType(v, Type::String, place);
    return v.string;
}

const Value& SceneParser::array(const Value& v, const std::string& place, size_t size, const char* what) const {
    expectType(v, Type::Array, place);
    if (v.array.size() != size)
        fail(place, "expected an array of " + std::to_string(size) + " " + what + ", got " +
                        std::to_string(v.array.size()) + " element" + (v.array.size() == 1 ? "" : "s"));
    return v;
}

V3d SceneParser::vec3(const Value& v, const std::string& place) const {
    const Value& a = array(v, place, 3, "numbers");
    return V3d(number(a.array[0], item(place, 0)), number(a.array[1], item(place, 1)),
               number(a.array[2], item(place, 2)));
}

V3d SceneParser::direction(const Value& v, const std::string& place) const {
    const V3d d = vec3(v, place);
    if (d == V3d(0, 0, 0)) fail(place, "direction must be non-zero");
    return d;
}

Rgbd SceneParser::colour(const Value& v, const std::string& place, bool fraction) const {
    const Value& a = array(v, place, 3, "numbers (R, G, B)");
    double c[3];
    for (size_t i = 0; i < 3; ++i) {
        c[i] = fraction ? numberIn(a.array[i], item(place, i), 0, false, 1, false)
                        : number(a.array[i], item(place, i));
        if (!fraction && c[i] < 0) fail(item(place, i), "must be at least 0, got " + shortestNumber(c[i]));
    }
    return Rgbd(c[0], c[1], c[2]);
}

std::string SceneParser::parseName(const Value& v, const std::string& place) {
    const std::string here = member(place, "name");
    std::string name = text(required(v, place, "name"), here);
    const auto [it, fresh] = names_.emplace(name, here);
    if (!fresh) fail(here, "name " + quote(name) + " is already used by " + it->second);
    return name;
}

}  // namespace lucerna
