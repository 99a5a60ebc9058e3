// The numbers the bench programs take on their command lines, read as the verbs read
// theirs (game/cli/args.h): std::atoi reads "abc" as 0 and "12x" as 12, so a mistyped
// option ran another benchmark than the one asked for; here the whole text must be a
// decimal number in range (a whole one: digits only), or the program says which option,
// what it got and what it expected.
#pragma once

#include "game/cli/args.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace bench_args {

/// The value `text` of option `name` when all of it is a number in [lo, hi] (and a whole
/// number if `whole`); else prints "<program>: <name> expects ..., got '<text>'" on
/// stderr and returns nothing.
inline std::optional<double> numberOption(const char* program, const char* name,
                                          const char* text, double lo, double hi,
                                          bool whole) {
    const std::string s = text;
    const bool number = whole ? game::cli::isWholeNumber(s) : game::cli::isDecimal(s);
    const double v = number ? std::strtod(text, nullptr) : NAN;
    if (std::isfinite(v) && v >= lo && v <= hi) return v;
    if (whole)
        std::fprintf(stderr, "%s: %s expects a whole number in %.0f..%.0f, got '%s'\n", program,
                     name, lo, hi, text);
    else
        std::fprintf(stderr, "%s: %s expects a number in %g..%g, got '%s'\n", program, name, lo,
                     hi, text);
    return std::nullopt;
}

/// A whole number for option `name` into `out`; false (and the message) if `text` is not one.
template <class Int>
bool countOption(const char* program, const char* name, const char* text, Int& out, double lo,
                 double hi = 1e9) {
    const auto v = numberOption(program, name, text, lo, hi, true);
    if (v) out = static_cast<Int>(*v);
    return v.has_value();
}

/// A number for option `name` into `out`; false (and the message) if `text` is not one.
inline bool realOption(const char* program, const char* name, const char* text, double& out,
                       double lo, double hi) {
    const auto v = numberOption(program, name, text, lo, hi, false);
    if (v) out = *v;
    return v.has_value();
}

} // namespace bench_args
