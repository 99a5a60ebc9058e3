#include "game/cli/args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace game::cli {

Args::Args(std::string verb, int argc, const char* const* argv, int first,
           std::set<std::string> flags)
    : verb_(std::move(verb)), flagNames_(std::move(flags)) {
    flagNames_.insert("json");
    flagNames_.insert("help");
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (a.rfind("--", 0) != 0 || a.size() == 2) {
            positionals_.push_back(a);
            continue;
        }
        std::string name = a.substr(2), value;
        const auto eq = name.find('=');
        bool hasValue = false;
        if (eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
            hasValue = true;
        }
        if (flagNames_.count(name)) {
            if (hasValue) fail("--" + name + " takes no value");
            flagsGiven_.insert(name);
            continue;
        }
        if (!hasValue) {
            // Last on the line, or followed by another option, with no value: an option
            // that needs one, or an unknown flag; which it is shows when the verb asks for
            // it (text() or rejectUnknown()). (No value starts with "--": a negative
            // number has one dash, and --name=VALUE still takes anything.)
            const std::string next = i + 1 < argc ? argv[i + 1] : "";
            if (i + 1 >= argc || (next.rfind("--", 0) == 0 && next.size() > 2)) {
                missingValue_.insert(name);
                continue;
            }
            value = argv[++i];
        }
        if (value.empty()) fail("--" + name + " needs a value, got an empty one");
        if (values_.count(name)) fail("--" + name + " given twice");
        values_[name] = value;
    }
}

void Args::fail(const std::string& message) const {
    throw UsageError("artillery " + verb_ + ": " + message + " (see artillery " + verb_ +
                     " --help)");
}

bool Args::flag(const std::string& name) const {
    asked_.insert(name);
    return flagsGiven_.count(name) != 0;
}

std::optional<std::string> Args::text(const std::string& name) const {
    asked_.insert(name);
    if (missingValue_.count(name)) fail("--" + name + " needs a value");
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::string Args::text(const std::string& name, const std::string& fallback) const {
    return text(name).value_or(fallback);
}

bool isDecimal(const std::string& s) {
    std::size_t i = 0, digits = 0;
    auto isDigit = [&](std::size_t k) { return k < s.size() && s[k] >= '0' && s[k] <= '9'; };
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    while (isDigit(i)) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (isDigit(i)) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        if (!isDigit(i)) return false;
        while (isDigit(i)) ++i;
    }
    return i == s.size();
}

bool isWholeNumber(const std::string& s) {
    const std::size_t first = s.starts_with('-') ? 1 : 0;
    return s.size() > first && s.find_first_not_of("0123456789", first) == std::string::npos;
}

double Args::parseNumber(const std::string& name, const std::string& raw, double lo, double hi,
                         const char* what) const {
    const char* s = raw.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s, &end);
    std::ostringstream range;
    range << "a number in [" << lo << ", " << hi << "]" << (what && *what ? " " : "")
          << (what ? what : "");
    if (!isDecimal(raw) || end != s + raw.size() || !std::isfinite(v))
        fail("--" + name + " expects " + range.str() + ", got '" + raw + "'");
    if (v < lo || v > hi)
        fail("--" + name + " expects " + range.str() + ", got " + raw);
    return v;
}

double Args::number(const std::string& name, double fallback, double lo, double hi,
                    const char* what) const {
    auto t = text(name);
    return t ? parseNumber(name, *t, lo, hi, what) : fallback;
}

double Args::requiredNumber(const std::string& name, double lo, double hi,
                            const char* what) const {
    auto t = text(name);
    if (!t) fail("--" + name + " is required");
    return parseNumber(name, *t, lo, hi, what);
}

long long Args::integer(const std::string& name, long long fallback, long long lo,
                        long long hi) const {
    auto t = text(name);
    if (!t) return fallback;
    const char* s = t->c_str();
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s, &end, 10);
    if (!isWholeNumber(*t) || end != s + t->size() || errno == ERANGE || v < lo || v > hi)
        fail("--" + name + " expects a whole number in [" + std::to_string(lo) + ", " +
             std::to_string(hi) + "], got '" + *t + "'");
    return v;
}

phys::Vec2 Args::vec2(const std::string& name, phys::Vec2 fallback) const {
    auto t = text(name);
    if (!t) return fallback;
    const auto comma = t->find(',');
    if (comma == std::string::npos || t->find(',', comma + 1) != std::string::npos)
        fail("--" + name + " expects X,Y (two numbers and a comma), got '" + *t + "'");
    const double big = 1e9;
    return {parseNumber(name, t->substr(0, comma), -big, big, "for X"),
            parseNumber(name, t->substr(comma + 1), -big, big, "for Y")};
}

phys::Vec2 Args::requiredVec2(const std::string& name) const {
    if (!has(name)) {
        asked_.insert(name);
        fail("--" + name + " X,Y is required");
    }
    return vec2(name, {});
}

void Args::rejectUnknown() const {
    for (const auto& name : missingValue_)
        if (!asked_.count(name)) fail("unknown option --" + name);
    for (const auto& [name, value] : values_)
        if (!asked_.count(name)) fail("unknown option --" + name);
    for (const auto& name : flagsGiven_)
        if (!asked_.count(name)) fail("unknown option --" + name);
    if (!positionals_.empty() && !asked_.count("<positional>"))
        fail("unexpected argument '" + positionals_.front() + "'");
}

} // namespace game::cli
