#include "game/files/json_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace game {

namespace {

/// "line L, column C" of a byte offset, which is what an editor shows.
std::string lineColumn(const std::string& text, std::size_t offset) {
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

/// A number literal beyond what a double holds (1e+315, four hundred digits): the JSON
/// grammar allows it, nlohmann refuses it with out_of_range 406 (not a parse_error), and
/// names the literal but not where it is.
LoadError numberOutOfRange(const std::string& file, const std::string& text,
                           const std::string& what) {
    const auto open = what.find('\''), close = what.rfind('\'');
    const std::string literal =
        open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
    const std::string shown = literal.size() > 24 ? literal.substr(0, 24) + "..." : literal;
    return LoadError(file, at != std::string::npos ? lineColumn(text, at) : "$",
                     "number out of range: " + shown +
                         " does not fit in a double (magnitude up to 1.8e308)");
}

} // namespace

namespace {

/// The byte offset just past the `count`-th occurrence of an opening bracket or brace at
/// depth `depth` outside strings: where nesting first goes deeper than allowed.
std::size_t deepestOpening(const std::string& text, int limit) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string::npos;
}

/// Refuses a key given twice in one object (JSON allows it; the last one would silently
/// win), while nlohmann parses: one set of keys per open object.
struct DuplicateKeys {
    std::vector<std::set<std::string>> open;
    bool operator()(int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using E = nlohmann::json::parse_event_t;
        if (event == E::object_start) open.emplace_back();
        else if (event == E::object_end) open.pop_back();
        else if (event == E::key && !open.empty() && !open.back().insert(parsed.get<std::string>()).second)
            throw duplicate{parsed.get<std::string>()};
        return true;
    }
    struct duplicate {
        std::string key;
    };
};

} // namespace

nlohmann::json parseJson(const std::string& file, const std::string& text) {
    // Depth first, on the raw text: nlohmann's parser and the values it builds recurse.
    if (const std::size_t at = deepestOpening(text, kMaxJsonDepth); at != std::string::npos)
        throw LoadError(file, lineColumn(text, at),
                        "arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) +
                            " levels (no file format of the game needs more than 5)");
    try {
        return nlohmann::json::parse(text, DuplicateKeys{});
    } catch (const DuplicateKeys::duplicate& d) {
        // nlohmann does not say where the parser is; the key's second occurrence is.
        const std::string quoted = "\"" + d.key + "\"";
        const std::size_t first = text.find(quoted);
        const std::size_t second = first == std::string::npos ? first : text.find(quoted, first + 1);
        throw LoadError(file, second == std::string::npos ? "$" : lineColumn(text, second),
                        "the key " + quoted + " is given twice in one object (give it once)");
    } catch (const nlohmann::json::parse_error& e) {
        const std::string what = e.what();
        const auto cut = what.find("syntax error");
        throw LoadError(file, lineColumn(text, e.byte > 0 ? e.byte - 1 : 0),
                        "not valid JSON: " +
                            (cut != std::string::npos ? what.substr(cut) : what));
    } catch (const nlohmann::json::out_of_range& e) {
        throw numberOutOfRange(file, text, e.what());
    }
}

Node::Node(const nlohmann::json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {}

void Node::fail(const std::string& message) const { throw LoadError(file_, path_, message); }

std::string Node::describe() const {
    // Only scalars are written out: an array or object may be huge or deep, and its
    // count is what the message needs. Invalid UTF-8 in a string is escaped, not thrown.
    std::string s;
    if (!value_.is_array() && !value_.is_object())
        s = value_.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (characterCount(s) > 40) s = s.substr(0, 37) + "...";
    switch (value_.type()) {
    case nlohmann::json::value_t::string: return "the string " + s;
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array of " + std::to_string(value_.size());
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return s;
    default: return s;
    }
}

bool Node::has(const std::string& key) const {
    asked_.insert(key);
    return value_.is_object() && value_.contains(key) && !value_.at(key).is_null();
}

Node Node::at(const std::string& key) const {
    asked_.insert(key);
    if (!value_.is_object()) fail("expected an object with field \"" + key + "\", got " + describe());
    if (!value_.contains(key)) fail("missing field \"" + key + "\"");
    return Node(value_.at(key), file_, path_ + "." + key);
}

std::optional<Node> Node::find(const std::string& key) const {
    asked_.insert(key);
    if (!value_.is_object()) fail("expected an object, got " + describe());
    if (!value_.contains(key) || value_.at(key).is_null()) return std::nullopt;
    return Node(value_.at(key), file_, path_ + "." + key);
}

std::vector<Node> Node::elements(std::size_t maxCount, std::size_t minCount) const {
    if (!value_.is_array()) fail("expected an array, got " + describe());
    if (value_.size() > maxCount)
        fail("expected at most " + std::to_string(maxCount) + " element(s), got " +
             std::to_string(value_.size()));
    if (value_.size() < minCount)
        fail("expected at least " + std::to_string(minCount) + " element(s), got " +
             std::to_string(value_.size()));
    std::vector<Node> out;
    out.reserve(value_.size());
    for (std::size_t i = 0; i < value_.size(); ++i)
        out.emplace_back(value_[i], file_, path_ + "[" + std::to_string(i) + "]");
    return out;
}

double Node::number(double lo, double hi, const char* unit) const {
    std::ostringstream range;
    range << "a number in [" << lo << ", " << hi << "]" << (unit && *unit ? " " : "")
          << (unit ? unit : "");
    if (!value_.is_number()) fail("expected " + range.str() + ", got " + describe());
    const double v = value_.get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        fail("expected " + range.str() + ", got " + describe());
    return v;
}

long long Node::integer(long long lo, long long hi) const {
    const std::string range =
        "a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!value_.is_number_integer()) fail("expected " + range + ", got " + describe());
    // An unsigned past the largest long long would wrap in get<long long>(); every one up
    // to it is taken exactly (the 9e18 this compared with was a double below 2^63 - 1, the
    // largest seed a level may name).
    if (value_.is_number_unsigned() &&
        value_.get<unsigned long long>() >
            static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
        fail("expected " + range + ", got " + describe());
    const long long v = value_.get<long long>();
    if (v < lo || v > hi) fail("expected " + range + ", got " + describe());
    return v;
}

bool Node::boolean() const {
    if (!value_.is_boolean()) fail("expected true or false, got " + describe());
    return value_.get<bool>();
}

std::string Node::string(std::size_t maxLength) const {
    if (!value_.is_string()) fail("expected a string, got " + describe());
    const auto& s = value_.get_ref<const std::string&>();
    if (characterCount(s) > maxLength)
        fail("expected a string of at most " + std::to_string(maxLength) + " characters, got " +
             std::to_string(characterCount(s)));
    return s;
}

std::string Node::choice(const std::vector<std::string>& allowed) const {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
    if (!value_.is_string()) fail("expected one of " + list + ", got " + describe());
    const std::string s = value_.get<std::string>();
    for (const auto& a : allowed)
        if (s == a) return s;
    fail("expected one of " + list + ", got " + describe());
}

phys::Vec2 Node::vec2(double limit) const {
    if (!value_.is_array() || value_.size() != 2 || !value_[0].is_number() ||
        !value_[1].is_number())
        fail("expected [x, y] (two numbers), got " + describe());
    const auto e = elements(2);
    return {e[0].number(-limit, limit, "m"), e[1].number(-limit, limit, "m")};
}

double Node::number(const std::string& key, double lo, double hi, const char* unit) const {
    return at(key).number(lo, hi, unit);
}
double Node::number(const std::string& key, double fallback, double lo, double hi,
                    const char* unit) const {
    auto n = find(key);
    return n ? n->number(lo, hi, unit) : fallback;
}
long long Node::integer(const std::string& key, long long fallback, long long lo,
                        long long hi) const {
    auto n = find(key);
    return n ? n->integer(lo, hi) : fallback;
}
bool Node::boolean(const std::string& key, bool fallback) const {
    auto n = find(key);
    return n ? n->boolean() : fallback;
}
std::string Node::string(const std::string& key) const { return at(key).string(); }
std::string Node::string(const std::string& key, const std::string& fallback) const {
    auto n = find(key);
    return n ? n->string() : fallback;
}
phys::Vec2 Node::vec2(const std::string& key) const { return at(key).vec2(); }
phys::Vec2 Node::vec2(const std::string& key, phys::Vec2 fallback) const {
    auto n = find(key);
    return n ? n->vec2() : fallback;
}

void Node::finish() const {
    if (!value_.is_object()) return;
    for (auto it = value_.begin(); it != value_.end(); ++it)
        if (!asked_.count(it.key())) {
            std::string known;
            for (const auto& k : asked_) known += (known.empty() ? "" : ", ") + k;
            fail("unknown field \"" + it.key() + "\" (known fields here: " + known + ")");
        }
}

} // namespace game
