#include "mutate.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "support/small_room.h"

namespace luxplan::fuzz {
namespace {

using Json = nlohmann::ordered_json;
using Rng = std::mt19937_64;

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

uint64_t splitmix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

size_t pick(Rng& rng, size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng); }
bool chance(Rng& rng, double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
template <class T>
const T& pickOf(Rng& rng, const std::vector<T>& v) { return v[pick(rng, v.size())]; }

// ---- JSON trees ----

struct Node {
    Json::json_pointer ptr;
    std::string key;  // the member name it is under, or the enclosing array's key
};

void collect(const Json& j, const Json::json_pointer& ptr, const std::string& key, std::vector<Node>& out) {
    out.push_back({ptr, key});
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it) collect(it.value(), ptr / it.key(), it.key(), out);
    else if (j.is_array())
        for (size_t i = 0; i < j.size(); ++i) collect(j[i], ptr / i, key, out);
}

std::vector<Node> nodes(const Json& j) {
    std::vector<Node> out;
    collect(j, Json::json_pointer(), "", out);
    return out;
}

std::vector<Node> filter(const Json& doc, const std::vector<Node>& all, const std::function<bool(const Node&, const Json&)>& keep) {
    std::vector<Node> out;
    for (const Node& n : all)
        if (keep(n, doc.at(n.ptr))) out.push_back(n);
    return out;
}

// Strings the mutations set may hold invalid UTF-8: written replaced (U+FFFD).
std::string dump(const Json& j, int indent = -1) { return j.dump(indent, ' ', false, Json::error_handler_t::replace); }

const std::vector<std::string> kExtremeNumbers = {"0", "-0", "-1", "1e-300", "1e300", "-1e300", "1.7976931348623157e308", "1e6",
                                                  "2147483648", "4294967296", "-2147483649", "9223372036854775807",
                                                  "18446744073709551616", "1e20", "0.5", "3", "100000000", "-1e-320", "1e-9"};

Json extremeNumber(Rng& rng) { return Json::parse(pickOf(rng, kExtremeNumbers)); }

Json otherType(Rng& rng) {
    static const std::vector<std::string> v = {"\"x\"", "true", "null", "[]", "{}", "[1,2,3]", "0", "[0,0]", "{\"a\":1}", "\"\"",
                                               "[[1,2],[3,4]]", "-5"};
    return Json::parse(pickOf(rng, v));
}

bool isCoordinateKey(const std::string& k) {
    static const std::vector<std::string> keys = {"position", "center", "min", "max", "eye", "origin", "translate"};
    return std::find(keys.begin(), keys.end(), k) != keys.end();
}

// Generic tree mutations: the result may be valid or not.
std::string genericJson(Rng& rng, Json doc, std::string& mutation) {
    std::vector<Node> all = nodes(doc);
    const int op = int(pick(rng, 7));
    switch (op) {
        case 0: {
            mutation = "json.number";
            auto nums = filter(doc, all, [](const Node&, const Json& j) { return j.is_number(); });
            if (nums.empty()) break;
            for (int k = 0, n = 1 + int(pick(rng, 3)); k < n; ++k) doc[pickOf(rng, nums).ptr] = extremeNumber(rng);
            break;
        }
        case 1: {
            mutation = "json.type";
            const Node& n = pickOf(rng, all);
            if (n.ptr.empty()) break;
            doc[n.ptr] = otherType(rng);
            break;
        }
        case 2: {
            mutation = "json.delete";
            for (int k = 0, n = 1 + int(pick(rng, 2)); k < n; ++k) {
                all = nodes(doc);
                const Node& victim = pickOf(rng, all);
                if (victim.ptr.empty()) continue;
                Json& parent = doc[victim.ptr.parent_pointer()];
                const std::string last = victim.ptr.back();
                if (parent.is_object()) parent.erase(last);
                else if (parent.is_array()) parent.erase(parent.begin() + std::stol(last));
            }
            break;
        }
        case 3: {
            mutation = "json.duplicate";
            auto arrays = filter(doc, all, [](const Node&, const Json& j) { return j.is_array() && !j.empty(); });
            if (arrays.empty()) break;
            Json& a = doc[pickOf(rng, arrays).ptr];
            const size_t i = pick(rng, a.size());
            Json copy = a[i];
            for (int k = 0, n = chance(rng, 0.1) ? 50 : 1; k < n; ++k) a.insert(a.begin() + long(i), copy);
            break;
        }
        case 4: {
            mutation = "json.copy";
            const Node& from = pickOf(rng, all);
            const Node& to = pickOf(rng, all);
            if (to.ptr.empty()) break;
            Json sub = doc[from.ptr];
            doc[to.ptr] = sub;
            break;
        }
        case 5: {
            mutation = "json.string";
            auto strs = filter(doc, all, [](const Node&, const Json& j) { return j.is_string(); });
            if (strs.empty()) break;
            static const std::vector<std::string> v = {"", "x", "/dev/zero", "/dev/null", ".", "..", "/", "\xff\xfe", "a.b.c",
                                                       "9999-99-99T99:99+99:99", "2026-02-30T12:00+00:00", "NaN",
                                                       std::string(300, 'a'), "nonexistent.obj", "../../../../etc/passwd"};
            doc[pickOf(rng, strs).ptr] = pickOf(rng, v);
            break;
        }
        default: {
            mutation = "json.swap-keys";
            auto objs = filter(doc, all, [](const Node&, const Json& j) { return j.is_object() && j.size() >= 2; });
            if (objs.empty()) break;
            Json& o = doc[pickOf(rng, objs).ptr];
            auto a = std::next(o.begin(), long(pick(rng, o.size()))), b = std::next(o.begin(), long(pick(rng, o.size())));
            std::swap(a.value(), b.value());
            break;
        }
    }
    return dump(doc, chance(rng, 0.5) ? 2 : -1);
}

// Byte-level damage to any text: the result may be valid or not.
std::string bytes(Rng& rng, std::string s) {
    static const std::string alphabet = "{}[]\",:0123456789.eE-+ \n\t/\\nu";
    for (int k = 0, n = 1 + int(pick(rng, 6)); k < n && !s.empty(); ++k) {
        const size_t at = pick(rng, s.size());
        switch (pick(rng, 5)) {
            case 0: s[at] = chance(rng, 0.7) ? alphabet[pick(rng, alphabet.size())] : char(pick(rng, 256)); break;
            case 1: s.insert(at, 1, alphabet[pick(rng, alphabet.size())]); break;
            case 2: s.erase(at, 1 + pick(rng, 16)); break;
            case 3: {
                const size_t len = std::min(s.size() - at, 1 + pick(rng, 64));
                s.insert(pick(rng, s.size()), s.substr(at, len));
                break;
            }
            default: s.resize(at); break;
        }
    }
    return s;
}

// A truncation that leaves JSON unbalanced.
std::string truncateJson(Rng& rng, const std::string& s) {
    size_t end = s.find_last_not_of(" \n\t\r");
    if (end == std::string::npos || end < 2) return "";
    return s.substr(0, 1 + pick(rng, end - 1));
}

// ---- the scene's own mutations ----

Case sceneCase(const Seeds& seeds, Rng& rng) {
    const Seeds::SceneSeed& seed = pickOf(rng, seeds.scenes);
    Case c;
    c.files = seed.files;
    Json doc = Json::parse(seed.text);
    std::vector<Node> all = nodes(doc);
    std::string text;
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    auto setNumbers = [&](const std::function<bool(const Node&, const Json&)>& which, const std::vector<std::string>& values,
                          const std::string& name) {
        auto found = filter(doc, all, which);
        if (found.empty()) return false;
        doc[pickOf(rng, found).ptr] = Json::parse(pickOf(rng, values));
        c.mutation = name;
        return true;
    };
    if (r < 0.40) {
        c.expect = Expect::Either;
        text = genericJson(rng, doc, c.mutation);
    } else if (r < 0.48) {
        c.expect = Expect::Either;
        c.mutation = "json.bytes";
        text = bytes(rng, seed.text);
    } else if (r < 0.52) {
        // An entity wrapped in groups `depth` deep.
        auto entities = doc.find("entities");
        if (entities == doc.end() || !entities->is_array() || entities->empty()) return sceneCase(seeds, rng);
        static const std::vector<int> depths = {1, 5, 20, 31, 33, 40, 60, 200, 10000};
        const int depth = pickOf(rng, depths);
        // Built as text: a tree 10^4 deep would overflow the harness's own stack.
        const std::string inner = dump((*entities)[0]);
        (*entities)[0] = "FUZZ_DEEP_PLACEHOLDER";
        std::string nested;
        for (int k = depth - 1; k >= 0; --k) nested += "{\"name\": \"g" + std::to_string(k) + "\", \"children\": [";
        nested += inner;
        for (int k = 0; k < depth; ++k) nested += "]}";
        text = dump(doc);
        text.replace(text.find("\"FUZZ_DEEP_PLACEHOLDER\""), 23, nested);
        c.mutation = "json.children-deep";
        c.expect = depth > 32 ? Expect::Refuse : Expect::Either;
    } else if (r < 0.55) {
        const int depth = chance(rng, 0.5) ? 200 : 100000;
        const Node& n = pickOf(rng, all);
        text = dump(doc);
        if (n.ptr.empty()) return sceneCase(seeds, rng);
        doc[n.ptr] = nullptr;
        text = dump(doc);
        const size_t at = text.find("null");  // not necessarily n's, any is fine
        if (at == std::string::npos) return sceneCase(seeds, rng);
        text.replace(at, 4, std::string(size_t(depth), '[') + std::string(size_t(depth), ']'));
        c.mutation = "json.nest-arrays";
        c.expect = Expect::Refuse;  // deeper than the JSON depth limit
    } else if (r < 0.60) {
        auto objs = filter(doc, all, [](const Node&, const Json& j) { return j.is_object(); });
        doc[pickOf(rng, objs).ptr]["fuzz_unknown_key"] = 1;
        c.mutation = "json.unknown-key";
        c.expect = Expect::Refuse;
        text = dump(doc, 2);
    } else if (r < 0.66) {
        c.expect = Expect::Refuse;
        if (!setNumbers(
                [&](const Node& n, const Json& j) {
                    // An element of a coordinate array (a scalar "min" is a constraint's distance).
                    return j.is_number() && isCoordinateKey(n.key) && doc.at(n.ptr.parent_pointer()).is_array() &&
                           n.ptr.to_string().find("statistics") == std::string::npos;
                },
                {"1e6", "-1e6", "1e9", "1e308", "-1.7976931348623157e308", "100001"}, "json.coordinate-far"))
            return sceneCase(seeds, rng);
        text = dump(doc);
    } else if (r < 0.70) {
        c.expect = Expect::Refuse;
        // Sizes are positive; a flux may be 0 (a luminaire switched off).
        const bool flux = chance(rng, 0.3);
        if (!setNumbers(
                [&](const Node& n, const Json& j) {
                    return j.is_number() && (flux ? n.key == "flux_lm"
                                                  : n.key == "size" || n.key == "radius" || n.key == "width" || n.key == "height");
                },
                flux ? std::vector<std::string>{"-1", "-1e-9", "1e10", "1e308"}
                     : std::vector<std::string>{"0", "-1", "-1e-9", "1e10", "1e308"},
                "json.size-out-of-range"))
            return sceneCase(seeds, rng);
        text = dump(doc);
    } else if (r < 0.72) {
        c.expect = Expect::Refuse;
        c.mutation = "json.version";
        static const std::vector<std::string> v = {"0", "2", "\"1\"", "1.5", "null"};
        if (chance(rng, 0.2)) doc.erase("luxplan");
        else doc["luxplan"] = Json::parse(pickOf(rng, v));
        text = dump(doc);
    } else if (r < 0.76) {
        c.expect = Expect::Refuse;
        c.mutation = "json.count-range";
        static const std::vector<std::string> keys = {"iterations", "paths_per_point", "seed"};
        const std::string key = pickOf(rng, keys);
        static const std::vector<std::string> counts = {"2147483648", "1e10", "-1", "1.5", "9223372036854775808", "1e300", "\"5\""};
        static const std::vector<std::string> seedValues = {"18446744073709551616", "-1", "1.5", "1e300", "\"5\""};
        doc["optimizer"][key] = Json::parse(key == "seed" ? pickOf(rng, seedValues) : pickOf(rng, counts));
        text = dump(doc);
    } else if (r < 0.80) {
        c.expect = Expect::Refuse;
        c.mutation = "json.bad-reference";
        auto refs = filter(doc, all, [](const Node& n, const Json& j) {
            return j.is_string() && (n.key == "material" || n.key == "template" || n.key == "a" || n.key == "b" ||
                                     n.key == "ceiling" || n.key == "walls" || n.key == "floor");
        });
        if (refs.empty()) return sceneCase(seeds, rng);
        doc[pickOf(rng, refs).ptr] = "fuzz_no_such_name";
        text = dump(doc);
    } else if (r < 0.84) {
        c.expect = Expect::Refuse;
        c.mutation = "json.not-json";
        text = dump(doc, 2);
        static const std::vector<std::string> bad = {"NaN", "Infinity", "-Infinity", "1e", "0x10", "01", "+1", ".5", "1..2"};
        // Replace the value of a numeric member ("key": number).
        std::vector<size_t> starts;
        for (size_t i = 1; i + 1 < text.size(); ++i)
            if ((text[i] >= '0' && text[i] <= '9') && (text[i - 1] == ' ' || text[i - 1] == '[') ) starts.push_back(i);
        if (starts.empty()) return sceneCase(seeds, rng);
        const size_t at = pickOf(rng, starts);
        size_t end = at;
        while (end < text.size() && (isdigit((unsigned char)text[end]) || text[end] == '.' || text[end] == 'e' || text[end] == '-' ||
                                     text[end] == '+'))
            ++end;
        text.replace(at, end - at, pickOf(rng, bad));
    } else if (r < 0.88) {
        c.expect = Expect::Refuse;
        c.mutation = "json.truncate";
        text = truncateJson(rng, seed.text);
    } else if (r < 0.91) {
        c.expect = Expect::Accept;
        c.mutation = "json.identity";
        c.measure = chance(rng, 0.5);
        text = seed.text;
    } else if (r < 0.95) {
        c.expect = Expect::Accept;
        c.mutation = "json.reformat";
        text = nlohmann::json::parse(seed.text).dump(int(pick(rng, 4)) - 1);  // keys sorted
    } else {
        c.expect = Expect::Accept;
        c.mutation = "json.valid-counts";
        if (chance(rng, 0.5))
            doc["optimizer"]["seed"] = std::uniform_int_distribution<uint64_t>(1ull << 31, (1ull << 63) - 1)(rng);
        else
            doc["optimizer"]["iterations"] = std::uniform_int_distribution<int64_t>(1, 2147483647)(rng);
        text = dump(doc);
    }
    if (c.expect != Expect::Refuse && !c.measure) c.measure = chance(rng, 0.08);
    c.files["scene.json"] = text;
    return c;
}

// ---- layouts ----

Case layoutCase(const Seeds& seeds, Rng& rng) {
    std::vector<const Seeds::SceneSeed*> with;
    for (const auto& s : seeds.scenes)
        if (!s.layout.empty() && s.layout.find("position") != std::string::npos) with.push_back(&s);
    if (with.empty()) return sceneCase(seeds, rng);
    const Seeds::SceneSeed& seed = *pickOf(rng, with);
    Case c;
    c.files = seed.files;
    c.files["scene.json"] = seed.text;
    c.layout = "layout.json";
    Json doc = Json::parse(seed.layout);
    std::vector<Node> all = nodes(doc);
    std::string text;
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    Json& entities = doc["entities"];
    const std::string entity = std::next(entities.begin(), long(pick(rng, entities.size()))).key();
    if (r < 0.45) {
        c.expect = Expect::Either;
        text = genericJson(rng, doc, c.mutation);
        c.mutation = "layout." + c.mutation;
    } else if (r < 0.55) {
        c.expect = Expect::Either;
        c.mutation = "layout.bytes";
        text = bytes(rng, seed.layout);
    } else if (r < 0.65) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.far";
        static const std::vector<std::string> v = {"1e9", "-1e6", "1e308", "100001"};
        Json& p = entities[entity]["position"];
        p[pick(rng, p.size())] = Json::parse(pickOf(rng, v));
        text = dump(doc);
    } else if (r < 0.72) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.unknown-entity";
        entities["fuzz.no.such"] = entities[entity];
        text = dump(doc);
    } else if (r < 0.78) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.unknown-key";
        if (chance(rng, 0.5)) entities[entity]["fuzz_key"] = 1;
        else doc["fuzz_key"] = 1;
        text = dump(doc);
    } else if (r < 0.84) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.region-range";
        static const std::vector<std::string> v = {"1000", "-1", "2147483648", "1.5", "\"0\""};
        entities[entity]["region"] = Json::parse(pickOf(rng, v));
        text = dump(doc);
    } else if (r < 0.88) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.rotation-range";
        static const std::vector<std::string> v = {"1e300", "-1e308", "\"90\"", "[90]", "null"};
        entities[entity]["rotation"] = Json::parse(pickOf(rng, v));
        text = dump(doc);
    } else if (r < 0.93) {
        c.expect = Expect::Refuse;
        c.mutation = "layout.truncate";
        text = truncateJson(rng, seed.layout);
    } else {
        c.expect = Expect::Accept;
        c.mutation = "layout.identity";
        text = seed.layout;
    }
    if (c.expect != Expect::Refuse) c.measure = chance(rng, 0.1);
    c.files["layout.json"] = text;
    return c;
}

// ---- meshes ----

const std::string kMeshScene = test::smallRoomScene(
    R"(, {"name": "m", "mesh": "MESH", "material": "wall", "transform": {"translate": [3, 2, 0.5]}})");

// The mesh as a static item, or as a part of the movable desk (half of the time).
std::string meshScene(const std::string& mesh, Rng& rng) {
    Json s = Json::parse(kMeshScene);
    if (chance(rng, 0.5)) {
        s["geometry"][1]["mesh"] = mesh;
    } else {
        s["geometry"].erase(1);
        s["entities"][0]["parts"].push_back(
            Json{{"mesh", mesh}, {"material", "wall"}, {"transform", Json{{"translate", Json::array({0, 0, 0.9})}, {"scale", 0.2}}}});
    }
    return s.dump(2);
}

std::string base64Decode(const std::string& in) {
    std::string out;
    int val = 0, bits = -8;
    for (unsigned char ch : in) {
        int d = ch >= 'A' && ch <= 'Z' ? ch - 'A' : ch >= 'a' && ch <= 'z' ? ch - 'a' + 26 : ch >= '0' && ch <= '9' ? ch - '0' + 52
              : ch == '+' ? 62 : ch == '/' ? 63 : -1;
        if (d < 0) break;
        val = (val << 6) + d;
        bits += 6;
        if (bits >= 0) {
            out.push_back(char((val >> bits) & 0xff));
            bits -= 8;
        }
    }
    return out;
}

void put32(std::string& s, uint32_t v) {
    for (int k = 0; k < 4; ++k) s.push_back(char((v >> (8 * k)) & 0xff));
}

// A binary glTF of a .gltf whose one buffer is a data: URI ("" if it is not).
std::string toGlb(const std::string& gltf) {
    Json doc = Json::parse(gltf);
    if (!doc.contains("buffers") || doc["buffers"].size() != 1) return "";
    const std::string uri = doc["buffers"][0].value("uri", "");
    const size_t comma = uri.find(";base64,");
    if (uri.rfind("data:", 0) != 0 || comma == std::string::npos) return "";
    std::string bin = base64Decode(uri.substr(comma + 8));
    doc["buffers"][0].erase("uri");
    doc["buffers"][0]["byteLength"] = bin.size();
    std::string json = doc.dump();
    while (json.size() % 4) json.push_back(' ');
    while (bin.size() % 4) bin.push_back('\0');
    std::string glb = "glTF";
    put32(glb, 2);
    put32(glb, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    put32(glb, uint32_t(json.size()));
    glb += "JSON";
    glb += json;
    put32(glb, uint32_t(bin.size()));
    glb += std::string("BIN\0", 4);
    glb += bin;
    return glb;
}

std::vector<std::string> splitLines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

// Replaces one whitespace-separated token of `line` that looks like a number.
bool replaceNumberToken(Rng& rng, std::string& line, const std::vector<std::string>& values) {
    std::vector<std::pair<size_t, size_t>> tokens;
    for (size_t i = 0; i < line.size();) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '/' || line[i] == '\r')) ++i;
        size_t j = i;
        while (j < line.size() && !(line[j] == ' ' || line[j] == '\t' || line[j] == ',' || line[j] == '/' || line[j] == '\r')) ++j;
        if (j > i && (isdigit((unsigned char)line[i]) || line[i] == '-' || line[i] == '.' || line[i] == '+')) tokens.push_back({i, j - i});
        i = j;
    }
    if (tokens.empty()) return false;
    auto [at, len] = pickOf(rng, tokens);
    line.replace(at, len, pickOf(rng, values));
    return true;
}

const std::vector<std::string> kTokenValues = {"0", "-1", "1e38", "1e39", "-1e39", "1e6", "1e-40", "nan", "inf", "-inf", "2147483648",
                                               "99999999999", "1.5", "+", "abc", "-0", "100000000", "1e308", "", "3"};

Case objCase(const Seeds& seeds, Rng& rng) {
    const auto& [name, original] = pickOf(rng, seeds.objs);
    Case c;
    c.files["scene.json"] = meshScene("m.obj", rng);
    std::vector<std::string> lines = splitLines(original);
    int vertices = 0;
    for (const auto& l : lines) vertices += l.rfind("v ", 0) == 0;
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    std::string text;
    if (r < 0.40) {
        c.expect = Expect::Either;
        c.mutation = "obj.lines";
        static const std::vector<std::string> inserts = {"f 1 2 3", "f 1", "f 1 2", "v 1 2", "vt 0 0", "vn 0 0 1", "f 1/1 2/2 3/3",
                                                         "f -1 -2 -3", "o x", "g g", "usemtl m", "s 1", "l 1 2", "mtllib /dev/zero",
                                                         "mtllib missing.mtl", "f 1//1 2//2 3//3", "p 1", "f 1 2 3 4 5 6 7 8",
                                                         "v 1 2 3 4", "f 0 0 0", "v", "f"};
        for (int k = 0, n = 1 + int(pick(rng, 4)); k < n; ++k) {
            const size_t at = pick(rng, lines.size());
            switch (pick(rng, 5)) {
                case 0: if (!lines.empty()) lines.erase(lines.begin() + long(at)); break;
                case 1: if (!lines.empty()) lines.insert(lines.begin() + long(at), lines[at]); break;
                case 2: if (!lines.empty()) replaceNumberToken(rng, lines[at], kTokenValues); break;
                case 3: lines.insert(lines.begin() + long(at), pickOf(rng, inserts)); break;
                default: if (lines.size() > 1) std::swap(lines[at], lines[pick(rng, lines.size())]); break;
            }
        }
        text = joinLines(lines);
    } else if (r < 0.50) {
        c.expect = Expect::Either;
        c.mutation = "obj.bytes";
        text = bytes(rng, original);
    } else if (r < 0.62) {
        c.expect = Expect::Refuse;
        c.mutation = "obj.face-out-of-range";
        const std::vector<std::string> v = {std::to_string(vertices + 1), std::to_string(vertices + 100), "100000000", "0",
                                            std::to_string(-vertices - 1), "2147483648", "-2147483649"};
        lines.push_back("f 1 2 " + pickOf(rng, v));
        text = joinLines(lines);
    } else if (r < 0.72) {
        c.expect = Expect::Refuse;
        c.mutation = "obj.vertex-bad";
        static const std::vector<std::string> v = {"nan", "inf", "-inf", "1e39", "1e6", "-1e300", "NaN"};
        std::vector<size_t> vs;
        for (size_t i = 0; i < lines.size(); ++i)
            if (lines[i].rfind("v ", 0) == 0) vs.push_back(i);
        if (vs.empty()) return objCase(seeds, rng);
        std::string& line = lines[pickOf(rng, vs)];
        std::istringstream in(line.substr(2));
        std::string x, y, z;
        in >> x >> y >> z;
        const int which = int(pick(rng, 3));
        line = "v " + (which == 0 ? pickOf(rng, v) : x) + " " + (which == 1 ? pickOf(rng, v) : y) + " " +
               (which == 2 ? pickOf(rng, v) : z);
        text = joinLines(lines);
    } else if (r < 0.77) {
        c.expect = Expect::Refuse;
        c.mutation = "obj.no-vertices";
        std::vector<std::string> kept;
        for (const auto& l : lines)
            if (l.rfind("v ", 0) != 0) kept.push_back(l);
        text = chance(rng, 0.2) ? std::string(chance(rng, 0.5) ? "" : "# nothing\n") : joinLines(kept);
    } else if (r < 0.82) {
        c.expect = Expect::Refuse;
        c.mutation = "obj.no-faces";
        std::vector<std::string> kept;
        for (const auto& l : lines)
            if (l.rfind("f ", 0) != 0) kept.push_back(l);
        text = joinLines(kept);
    } else {
        c.expect = Expect::Accept;
        c.mutation = "obj.valid";
        switch (pick(rng, 4)) {
            case 0: break;
            case 1: lines.insert(lines.begin() + long(pick(rng, lines.size())), "# a comment"); lines.push_back(""); break;
            case 2: lines.push_back("f 1 2 3"); break;
            default: lines.push_back("f -1 -2 -3"); break;
        }
        text = joinLines(lines);
        c.measure = chance(rng, 0.3);
    }
    if (c.expect != Expect::Refuse && !c.measure) c.measure = chance(rng, 0.1);
    c.files["m.obj"] = text;
    return c;
}

Case gltfCase(const Seeds& seeds, Rng& rng) {
    const auto& [name, original] = pickOf(rng, seeds.gltfs);
    Case c;
    c.files["scene.json"] = meshScene("m.gltf", rng);
    Json doc = Json::parse(original);
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    std::string text;
    if (r < 0.40) {
        c.expect = Expect::Either;
        text = genericJson(rng, doc, c.mutation);
        c.mutation = "gltf." + c.mutation;
    } else if (r < 0.47) {
        c.expect = Expect::Either;
        c.mutation = "gltf.bytes";
        text = bytes(rng, original);
    } else if (r < 0.85) {
        c.expect = Expect::Refuse;
        const int kind = int(pick(rng, 9));
        Json& acc = doc["accessors"][pick(rng, doc["accessors"].size())];
        switch (kind) {
            case 0:
                c.mutation = "gltf.accessor-count";
                acc["count"] = chance(rng, 0.5) ? Json(int64_t(acc["count"]) * 1000) : Json(2147483647);
                break;
            case 1: c.mutation = "gltf.position-type"; doc["accessors"][0]["type"] = chance(rng, 0.5) ? "SCALAR" : "VEC2"; break;
            case 2: {
                c.mutation = "gltf.view-past-buffer";
                Json& view = doc["bufferViews"][pick(rng, doc["bufferViews"].size())];
                if (chance(rng, 0.5)) view["byteLength"] = int64_t(view["byteLength"]) + 1000;
                else view["byteOffset"] = 1000000;
                break;
            }
            case 3: c.mutation = "gltf.bad-index"; doc["meshes"][0]["primitives"][0]["indices"] = 99; break;
            case 4: c.mutation = "gltf.bad-index"; doc["nodes"][0]["mesh"] = chance(rng, 0.5) ? 99 : -1; break;
            case 5: c.mutation = "gltf.cycle"; doc["nodes"][0]["children"] = Json::array({0}); break;
            case 6: {
                c.mutation = "gltf.shared-children";
                // 40 levels, each node reaching the next twice: 2^40 instances.
                Json nodesArr = Json::array();
                for (int k = 0; k < 40; ++k) nodesArr.push_back(Json{{"children", Json::array({k + 1, k + 1})}});
                nodesArr.push_back(Json{{"mesh", 0}});
                doc["nodes"] = nodesArr;
                doc["scenes"][0]["nodes"] = Json::array({0});
                break;
            }
            case 7: c.mutation = "gltf.uri-device"; doc["buffers"][0]["uri"] = chance(rng, 0.5) ? "/dev/zero" : "/dev/urandom"; break;
            default: {
                c.mutation = "gltf.index-past-vertices";
                // A uint16 index accessor holding 0..n-1 still, but over a shorter POSITION accessor.
                doc["accessors"][0]["count"] = 2;
                break;
            }
        }
        text = dump(doc);
    } else if (r < 0.90) {
        c.expect = Expect::Refuse;
        c.mutation = "gltf.truncate";
        text = truncateJson(rng, original);
    } else {
        c.expect = Expect::Accept;
        c.mutation = "gltf.valid";
        if (chance(rng, 0.5)) {
            doc["nodes"].push_back(Json{{"mesh", 0}, {"translation", Json::array({0.5, 0, 0})}});
            doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
        }
        text = doc.dump(int(pick(rng, 3)) - 1);
        c.measure = chance(rng, 0.3);
    }
    if (c.expect != Expect::Refuse && !c.measure) c.measure = chance(rng, 0.1);
    c.files["m.gltf"] = text;
    return c;
}

Case glbCase(const Seeds& seeds, Rng& rng) {
    const auto& [name, original] = pickOf(rng, seeds.glbs);
    Case c;
    c.files["scene.json"] = meshScene("m.glb", rng);
    std::string glb = original;
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    auto set32 = [&](size_t at, uint32_t v) {
        for (int k = 0; k < 4 && at + size_t(k) < glb.size(); ++k) glb[at + size_t(k)] = char((v >> (8 * k)) & 0xff);
    };
    const uint32_t jsonLength = uint32_t((unsigned char)glb[12]) | uint32_t((unsigned char)glb[13]) << 8 |
                                uint32_t((unsigned char)glb[14]) << 16 | uint32_t((unsigned char)glb[15]) << 24;
    const size_t binHeader = 20 + jsonLength;
    static const std::vector<uint32_t> lengths = {0, 1, 3, 7, 0x7fffffff, 0xffffffff, 0xfffffff0, 100000};
    if (r < 0.45) {
        c.expect = Expect::Either;
        c.mutation = "glb.bytes";
        glb = bytes(rng, glb);
    } else if (r < 0.60) {
        c.expect = Expect::Either;
        c.mutation = "glb.lengths";
        const std::vector<size_t> fields = {8, 12, binHeader};
        set32(pickOf(rng, fields), pickOf(rng, lengths));
    } else if (r < 0.75) {
        // The JSON chunk's text, mutated like a .gltf's (lengths fixed up).
        c.expect = Expect::Either;
        std::string json = glb.substr(20, jsonLength), mutation;
        json = genericJson(rng, Json::parse(json), mutation);
        while (json.size() % 4) json.push_back(' ');
        c.mutation = "glb." + mutation;
        std::string out = glb.substr(0, 12);
        put32(out, uint32_t(json.size()));
        out += "JSON" + json + glb.substr(binHeader);
        glb = out;
        set32(8, uint32_t(glb.size()));
    } else if (r < 0.90) {
        c.expect = Expect::Refuse;
        c.mutation = "glb.truncate";
        glb.resize(pick(rng, glb.size() - 4));
    } else {
        c.expect = Expect::Accept;
        c.mutation = "glb.valid";
        c.measure = chance(rng, 0.3);
    }
    if (c.expect != Expect::Refuse && !c.measure) c.measure = chance(rng, 0.1);
    c.files["m.glb"] = glb;
    return c;
}

// ---- photometric files ----

Case photometryCase(const Seeds& seeds, Rng& rng) {
    const bool ldt = !seeds.ldts.empty() && chance(rng, 0.4);
    const auto& [name, original] = pickOf(rng, ldt ? seeds.ldts : seeds.ies);
    const std::string file = ldt ? "p.ldt" : "p.ies";
    Case c;
    std::string scene = seeds.photometryScene;
    for (size_t at; (at = scene.find("PHOTOMETRY")) != std::string::npos;) scene.replace(at, 10, file);
    c.files["scene.json"] = scene;
    std::vector<std::string> lines = splitLines(original);
    // The first line of numbers: after TILT= in an IES file, line 1 onwards in EULUMDAT.
    size_t dataLine = 0;
    if (!ldt)
        for (size_t i = 0; i < lines.size(); ++i)
            if (lines[i].rfind("TILT", 0) == 0) dataLine = i + 1;
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    std::string text;
    if (r < 0.45) {
        c.expect = Expect::Either;
        c.mutation = "photometry.tokens";
        for (int k = 0, n = 1 + int(pick(rng, 4)); k < n && !lines.empty(); ++k) {
            const size_t at = pick(rng, lines.size());
            switch (pick(rng, 4)) {
                case 0: lines.erase(lines.begin() + long(at)); break;
                case 1: lines.insert(lines.begin() + long(at), lines[at]); break;
                default: replaceNumberToken(rng, lines[at], kTokenValues); break;
            }
        }
        text = joinLines(lines);
    } else if (r < 0.55) {
        c.expect = Expect::Either;
        c.mutation = "photometry.bytes";
        text = bytes(rng, original);
    } else if (r < 0.65) {
        c.expect = Expect::Refuse;
        c.mutation = "photometry.truncate";
        // Cut inside the header or early in the numbers: far too few values remain.
        const size_t keep = dataLine + pick(rng, std::max<size_t>(1, std::min<size_t>(lines.size() - dataLine, 4)));
        lines.resize(std::min(keep, lines.size()));
        text = joinLines(lines);
    } else if (r < 0.80) {
        c.expect = Expect::Refuse;
        c.mutation = "photometry.counts";
        static const std::vector<std::string> v = {"100000000", "2147483648", "-1", "0", "1e300", "nan"};
        if (ldt) {
            // EULUMDAT lines 4 (Mc, C planes) and 6 (Ng, gamma angles), 1-based.
            const size_t line = chance(rng, 0.5) ? 3 : 5;
            if (line < lines.size()) lines[line] = pickOf(rng, v);
        } else if (dataLine < lines.size()) {
            std::istringstream in(lines[dataLine]);
            std::vector<std::string> t;
            for (std::string s; in >> s;) t.push_back(s);
            const size_t which = chance(rng, 0.5) ? 3 : 4;  // vertical / horizontal angles
            if (which < t.size()) t[which] = pickOf(rng, v);
            std::string line;
            for (const auto& s : t) line += s + " ";
            lines[dataLine] = line;
        }
        text = joinLines(lines);
    } else if (r < 0.90) {
        c.expect = Expect::Refuse;
        c.mutation = "photometry.candela-bad";
        // A value in the candela table (the file's last lines).
        static const std::vector<std::string> v = {"nan", "inf", "-5", "1e300", "x"};
        const size_t at = lines.size() - 1 - pick(rng, std::min<size_t>(3, lines.size() - dataLine - 1));
        std::string& line = lines[at];
        if (line.find_first_of("0123456789") == std::string::npos) return photometryCase(seeds, rng);
        // Replace a whole token: the first one on the line.
        size_t s = line.find_first_not_of(" \t");
        size_t e = line.find_first_of(" \t\r", s);
        line.replace(s, (e == std::string::npos ? line.size() : e) - s, pickOf(rng, v));
        text = joinLines(lines);
    } else {
        c.expect = Expect::Accept;
        c.mutation = "photometry.valid";
        text = original;
        c.measure = chance(rng, 0.5);
    }
    if (c.expect != Expect::Refuse && !c.measure) c.measure = chance(rng, 0.1);
    c.files[file] = text;
    return c;
}

}  // namespace

Seeds loadSeeds(const std::filesystem::path& sourceDir) {
    Seeds seeds;
    std::vector<std::filesystem::path> files;
    for (const char* dir : {"scenes", "tests/data"})
        for (const auto& e : std::filesystem::recursive_directory_iterator(sourceDir / dir))
            if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& p : files) {
        const std::string ext = p.extension().string();
        const std::string rel = std::filesystem::relative(p, sourceDir).string();
        if (ext == ".obj") seeds.objs.push_back({rel, readFile(p)});
        else if (ext == ".gltf") {
            seeds.gltfs.push_back({rel, readFile(p)});
            if (std::string glb = toGlb(seeds.gltfs.back().second); !glb.empty()) seeds.glbs.push_back({rel + " as GLB", glb});
        } else if (ext == ".glb") seeds.glbs.push_back({rel, readFile(p)});
        else if (ext == ".ies" || ext == ".IES") seeds.ies.push_back({rel, readFile(p)});
        else if (ext == ".ldt" || ext == ".LDT") seeds.ldts.push_back({rel, readFile(p)});
        else if (ext == ".json" && rel.rfind("scenes/", 0) == 0) {
            Seeds::SceneSeed s;
            s.name = rel;
            s.text = readFile(p);
            Json doc;
            try {
                doc = Json::parse(s.text);
            } catch (const std::exception&) {
                continue;
            }
            if (!doc.is_object() || !doc.contains("luxplan")) continue;
            bool ok = true;
            for (const Node& n : nodes(doc)) {
                if ((n.key == "photometry" || n.key == "mesh" || n.key == "weather") && doc.at(n.ptr).is_string()) {
                    const std::string ref = doc.at(n.ptr);
                    if (ref.find('/') != std::string::npos || !std::filesystem::is_regular_file(p.parent_path() / ref)) ok = false;
                    else s.files[ref] = readFile(p.parent_path() / ref);
                }
            }
            if (!ok) continue;
            if (rel.find("photometry") != std::string::npos && seeds.photometryScene.empty()) {
                Json d = doc;
                for (const Node& n : nodes(d))
                    if (n.key == "photometry" && d.at(n.ptr).is_string()) d[n.ptr] = "PHOTOMETRY";
                seeds.photometryScene = d.dump(2);
            }
            s.layout = layoutFor(p);
            seeds.scenes.push_back(std::move(s));
        }
    }
    return seeds;
}

Case makeCase(const Seeds& seeds, std::uint64_t seed, std::uint64_t index) {
    Rng rng(splitmix(splitmix(seed) ^ index));
    const double r = std::uniform_real_distribution<double>(0, 1)(rng);
    Case c;
    if (r < 0.45 || (seeds.objs.empty() && seeds.ies.empty())) c = sceneCase(seeds, rng);
    else if (r < 0.60) c = layoutCase(seeds, rng);
    else if (r < 0.75 && !seeds.objs.empty()) c = objCase(seeds, rng);
    else if (r < 0.81 && !seeds.gltfs.empty()) c = gltfCase(seeds, rng);
    else if (r < 0.86 && !seeds.glbs.empty()) c = glbCase(seeds, rng);
    else if (!seeds.ies.empty() && !seeds.photometryScene.empty()) c = photometryCase(seeds, rng);
    else c = sceneCase(seeds, rng);
    if (!c.layout.empty() && !c.files.count(c.layout)) c.layout.clear();
    return c;
}

}  // namespace luxplan::fuzz
