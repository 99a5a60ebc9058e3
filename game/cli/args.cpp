#include "game/cli/args.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace game::cli {

namespace {

// The option names a --help text gives: each "--" followed by a lower-case name.
std::set<std::string> optionNamesIn(std::string_view usage) {
    std::set<std::string> names;
    auto isNameChar = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    };
    for (std::size_t at = usage.find("--"); at != std::string_view::npos;
         at = usage.find("--", at + 2)) {
        std::size_t end = at + 2;
        while (end < usage.size() && isNameChar(usage[end]))
            ++end;
        if (end > at + 2 && usage[at + 2] >= 'a' && usage[at + 2] <= 'z')
            names.emplace(usage.substr(at + 2, end - at - 2));
    }
    return names;
}

// The edits from a to b, each inserting, deleting or replacing one letter or swapping
// two side by side ("--form" for "--from" is one): the optimal string alignment distance.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                                d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

} // namespace

Args::Args(std::string verb, int argc, const char* const* argv, int first,
           std::set<std::string> flags, std::string_view usage)
    : verb_(std::move(verb)), flagNames_(std::move(flags)), usageNames_(optionNamesIn(usage)) {
    flagNames_.insert("json");
    flagNames_.insert("help");
    if (!usageNames_.empty()) usageNames_.insert({"json", "help"}); // every verb's, named or not
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
        if (!usageNames_.empty() && !usageNames_.count(name)) fail(unknownOption(name));
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

void Args::refuse(const std::string& message) const {
    throw UsageError("artillery " + verb_ + ": " + message);
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

std::string Args::unknownOption(const std::string& name) const {
    // Near: one edit for every three letters of the name, at least one.
    const std::string* nearest = nullptr;
    std::size_t best = std::max<std::size_t>(1, name.size() / 3) + 1;
    for (const std::string& known : usageNames_) {
        if (known == name) continue; // named by the help, but not for what was asked
        // Lengths apart by `best` or more are that many edits apart at least (and a long
        // argument costs no table of its length times the name's).
        const std::size_t apart =
            name.size() > known.size() ? name.size() - known.size() : known.size() - name.size();
        if (apart >= best) continue;
        const std::size_t d = editDistance(name, known);
        if (d < best) best = d, nearest = &known;
    }
    std::string message = "unknown option --" + name;
    if (nearest) message += " (did you mean --" + *nearest + "?)";
    return message;
}

void Args::rejectUnknown() const {
    for (const auto& name : missingValue_)
        if (!asked_.count(name)) fail(unknownOption(name));
    for (const auto& [name, value] : values_)
        if (!asked_.count(name)) fail(unknownOption(name));
    for (const auto& name : flagsGiven_)
        if (!asked_.count(name)) fail(unknownOption(name));
    if (!positionals_.empty() && !asked_.count("<positional>"))
        fail("unexpected argument '" + positionals_.front() + "'");
}

} // namespace game::cli
