// Reading JSON files with errors that say where and what: every message names the
// file, the JSON path ($.cannons[0].position) and what was expected. Used by levels,
// replays, command scripts and settings, so every loader reports errors the same way
// (a LoadError, game/files/text_file.h, which also reads and writes the files).
//
// A Node is a view of one JSON value at a path. Objects are read field by field;
// finish() then refuses any field nobody asked about, so a typo is an error instead
// of a silently ignored setting.
#pragma once

#include "game/files/text_file.h"
#include "physics/vec2.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace game {

/// How deep arrays and objects may nest in any file; the formats need 5 levels.
inline constexpr int kMaxJsonDepth = 64;

/// Parses text as JSON; a syntax error, nesting deeper than kMaxJsonDepth and a key given
/// twice in one object each become a LoadError with line and column.
nlohmann::json parseJson(const std::string& file, const std::string& text);

class Node {
  public:
    Node(const nlohmann::json& value, std::string file, std::string path = "$");
    ~Node() = default;

    const nlohmann::json& json() const { return value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const;

    bool isObject() const { return value_.is_object(); }
    bool has(const std::string& key) const;

    /// A field of this object; fails when missing.
    Node at(const std::string& key) const;
    /// A field of this object, or nullopt when missing (or null).
    std::optional<Node> find(const std::string& key) const;
    /// Elements of this array; fails when it is not an array or has too many.
    std::vector<Node> elements(std::size_t maxCount, std::size_t minCount = 0) const;

    // Typed reads of this value.
    double number(double lo, double hi, const char* unit = "") const;
    long long integer(long long lo, long long hi) const;
    bool boolean() const;
    std::string string(std::size_t maxLength = 256) const;
    /// One of the allowed strings.
    std::string choice(const std::vector<std::string>& allowed) const;
    /// [x, y] with both within [-limit, limit].
    phys::Vec2 vec2(double limit = 1e6) const;

    // Field shorthands: required and optional-with-default.
    double number(const std::string& key, double lo, double hi, const char* unit = "") const;
    double number(const std::string& key, double fallback, double lo, double hi,
                  const char* unit = "") const;
    long long integer(const std::string& key, long long fallback, long long lo, long long hi) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    std::string string(const std::string& key, const std::string& fallback) const;
    phys::Vec2 vec2(const std::string& key) const;
    phys::Vec2 vec2(const std::string& key, phys::Vec2 fallback) const;

    /// Refuses fields of this object that were never asked about.
    void finish() const;

  private:
    std::string describe() const; // short description of the value, for "got ..."
    const nlohmann::json& value_;
    std::string file_;
    std::string path_;
    mutable std::set<std::string> asked_;
};

} // namespace game
