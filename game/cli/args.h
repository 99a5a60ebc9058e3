// Command-line options of one verb: `--name value` pairs, `--flag`s and positionals,
// read through typed getters that refuse bad input with one clear message naming the
// option and what was expected (exit 2 on bad input, docs/cli.md).
#pragma once

#include "physics/vec2.h"

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace game::cli {

/// Bad input on the command line; the verb prints what() and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A failure during the work, after the input was accepted (a disk that fills while a
/// replay is written, a folder removed under a run): the verb prints what() and exits 3.
struct WorkError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Exit codes shared by every verb: 1 only ever means that a check the verb made failed
/// (a bad level for `check`, a diverged replay), never that the program did.
enum Exit { kOk = 0, kCheckFailed = 1, kBadInput = 2, kWorkFailed = 3 };

/// Decimal notation only: [+-] digits [. digits] [e [+-] digits], at least one digit in
/// the mantissa. strtod alone would also take "0x10", "inf", "nan" and leading spaces.
bool isDecimal(const std::string& s);
/// Whole-number notation only: digits, with an optional minus (strtoll alone would also
/// take " 12" and "+12").
bool isWholeNumber(const std::string& s);

class Args {
  public:
    /// Parses argv[first..argc). `flags` are options that take no value. With `usage`
    /// (the verb's --help text), an option it never names is refused at once, before
    /// the verb runs, with the nearest one it does name as a suggestion: a typo is
    /// reported as such, not as the option it was meant to be missing.
    Args(std::string verb, int argc, const char* const* argv, int first,
         std::set<std::string> flags = {}, std::string_view usage = {});

    bool flag(const std::string& name) const;
    bool has(const std::string& name) const { return values_.count(name) != 0 || missingValue_.count(name) != 0; }
    const std::vector<std::string>& positionals() const { return positionals_; }

    std::optional<std::string> text(const std::string& name) const;
    std::string text(const std::string& name, const std::string& fallback) const;
    /// A finite number, within [lo, hi]; `what` names the unit for the message.
    double number(const std::string& name, double fallback, double lo, double hi,
                  const char* what) const;
    double requiredNumber(const std::string& name, double lo, double hi, const char* what) const;
    long long integer(const std::string& name, long long fallback, long long lo,
                      long long hi) const;
    /// "X,Y" as a vector.
    phys::Vec2 vec2(const std::string& name, phys::Vec2 fallback) const;
    phys::Vec2 requiredVec2(const std::string& name) const;

    /// Throws if any option was given that the verb never asked about, so typos
    /// ("--sped") are reported instead of silently ignored.
    void rejectUnknown() const;
    [[noreturn]] void fail(const std::string& message) const;
    /// The same refusal without pointing at --help: for what the help cannot fix (a
    /// folder that does not take files).
    [[noreturn]] void refuse(const std::string& message) const;

  private:
    double parseNumber(const std::string& name, const std::string& raw, double lo, double hi,
                       const char* what) const;
    std::string verb_;
    std::map<std::string, std::string> values_;
    std::set<std::string> flagsGiven_;
    std::set<std::string> missingValue_; ///< options last on the line with no value
    std::set<std::string> flagNames_;
    std::set<std::string> usageNames_; ///< every --name the verb's --help text gives
    /// "unknown option --name", with the nearest name of the --help text if one is near.
    std::string unknownOption(const std::string& name) const;
    std::vector<std::string> positionals_;
    mutable std::set<std::string> asked_;
};

} // namespace game::cli
