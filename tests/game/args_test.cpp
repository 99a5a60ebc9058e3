// The command-line reader refuses bad input with a message naming option and range.
#include "game/cli/args.h"

#include <gtest/gtest.h>

using game::cli::Args;
using game::cli::UsageError;

namespace {
Args make(std::vector<const char*> argv) {
    argv.insert(argv.begin(), {"artillery", "solve"});
    return Args("solve", static_cast<int>(argv.size()), argv.data(), 2);
}
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(Args, ReadsNumbersVectorsAndFlags) {
    Args a = make({"--speed", "30", "--from=1.5,-2", "--json"});
    EXPECT_EQ(a.requiredNumber("speed", 0, 100, "m/s"), 30.0);
    EXPECT_EQ(a.requiredVec2("from"), (phys::Vec2{1.5, -2}));
    EXPECT_TRUE(a.flag("json"));
    a.rejectUnknown();
}

TEST(Args, BadInputNamesTheOptionAndWhatWasExpected) {
    Args a = make({"--speed", "fast", "--from", "1;2", "--to", "nan,3", "--n", "2.5"});
    EXPECT_NE(errorOf([&] { a.requiredNumber("speed", 0, 100, "m/s"); }).find(
                  "--speed expects a number in [0, 100] m/s, got 'fast'"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { a.requiredVec2("from"); }).find("--from expects X,Y"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { a.requiredVec2("to"); }).find("got 'nan'"), std::string::npos);
    EXPECT_NE(errorOf([&] { a.integer("n", 1, 0, 10); }).find("whole number"), std::string::npos);
    EXPECT_NE(errorOf([&] { a.requiredNumber("missing", 0, 1, ""); }).find("--missing is required"),
              std::string::npos);
}

TEST(Args, OutOfRangeAndUnknownOptionsAreRefused) {
    Args a = make({"--speed", "-3", "--sped", "3"});
    EXPECT_NE(errorOf([&] { a.requiredNumber("speed", 0, 100, "m/s"); }).find("got -3"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { a.rejectUnknown(); }).find("unknown option --sped"), std::string::npos);
    // Last on the line with no value: asked for, it needs one; never asked for, it is
    // unknown (a flag the verb does not have), not "needs a value".
    EXPECT_EQ(errorOf([] { make({"--speed"}).requiredNumber("speed", 0, 100, "m/s"); }),
              "artillery solve: --speed needs a value (see artillery solve --help)");
    EXPECT_EQ(errorOf([] { make({"--verbose"}).rejectUnknown(); }),
              "artillery solve: unknown option --verbose (see artillery solve --help)");
    EXPECT_EQ(errorOf([] { make({"--out="}); }),
              "artillery solve: --out needs a value, got an empty one (see artillery solve --help)");
    for (const char* notDecimal : {"0x10", "inf", "nan", " 3", "1e", ".", "+", "3,5"})
        EXPECT_NE(errorOf([&] { make({"--v", notDecimal}).requiredNumber("v", -1e9, 1e9, ""); })
                      .find("--v expects a number"),
                  std::string::npos)
            << notDecimal;
    for (const char* decimal : {"16", "-3.5", "+2", ".5", "5.", "1e3", "2.5E-2"})
        EXPECT_NO_THROW(make({"--v", decimal}).requiredNumber("v", -1e9, 1e9, "")) << decimal;
    EXPECT_NE(errorOf([] { make({"--a", "1", "--a", "2"}); }).find("given twice"),
              std::string::npos);
}

// With the verb's --help text, an option it never names is refused as the line is read,
// before a missing required option could be reported in its place, and the nearest name
// of the text within one edit for every three letters (a swap of two letters is one) is
// suggested.
TEST(Args, OptionsTheHelpNeverNamesAreRefusedAtOnceWithTheNearestSuggested) {
    const char* usage = "usage: artillery solve --from X,Y --to X,Y --speed V [--planet NAME]\n"
                        "  --gravity G   m/s^2 (Earth's by default; -- alone is no option)\n";
    auto read = [&](std::vector<const char*> argv) {
        argv.insert(argv.begin(), {"artillery", "solve"});
        return Args("solve", static_cast<int>(argv.size()), argv.data(), 2, {}, usage);
    };
    EXPECT_EQ(errorOf([&] {
                  read({"--form", "0,0", "--to", "4,0"});
              }),
              "artillery solve: unknown option --form (did you mean --from?) (see artillery "
              "solve --help)");
    EXPECT_EQ(errorOf([&] {
                  read({"--to", "4,0", "--sped=3"});
              }),
              "artillery solve: unknown option --sped (did you mean --speed?) (see artillery "
              "solve --help)");
    EXPECT_EQ(errorOf([&] {
                  read({"--plant", "mars"});
              }),
              "artillery solve: unknown option --plant (did you mean --planet?) (see artillery "
              "solve --help)");
    // Nothing within reach: no suggestion ("--x" is no typo of "--to").
    EXPECT_EQ(errorOf([&] { read({"--x"}); }),
              "artillery solve: unknown option --x (see artillery solve --help)");
    EXPECT_EQ(errorOf([&] {
                  read({"--frobnicate", "1"});
              }),
              "artillery solve: unknown option --frobnicate (see artillery solve --help)");
    // What the text names passes to the verb as before, --json and --help always.
    Args a = read({"--from", "0,0", "--to", "4,0", "--speed", "3", "--gravity", "9.8", "--json"});
    EXPECT_EQ(a.requiredNumber("gravity", 0, 100, "m/s^2"), 9.8);
    EXPECT_NO_THROW(read({"--help"}));
    // Named by the text but never asked for (a sub-command's option given to another):
    // unknown, and no suggestion of itself.
    EXPECT_EQ(errorOf([&] {
                  read({"--gravity", "9.8"}).rejectUnknown();
              }),
              "artillery solve: unknown option --gravity (see artillery solve --help)");
    // Without a text, unknown options wait for rejectUnknown, which suggests nothing.
    EXPECT_NO_THROW(make({"--form", "0,0"}));
}

TEST(Args, NumberNotationIsPlainDecimalAndWholeNumbersAreDigits) {
    using game::cli::isDecimal, game::cli::isWholeNumber;
    for (const char* good : {"12", "-3", "+0.5", "1e-3", "2.", ".5", "6.02E23"})
        EXPECT_TRUE(isDecimal(good)) << good;
    for (const char* bad : {"", " 1", "1 ", "0x10", "inf", "nan", "1e", ".", "-", "1,5"})
        EXPECT_FALSE(isDecimal(bad)) << "'" << bad << "'";
    for (const char* good : {"0", "12", "-3", "007"}) EXPECT_TRUE(isWholeNumber(good)) << good;
    for (const char* bad : {"", "-", "+12", " 12", "12 ", "1e3", "2.0", "0x1"})
        EXPECT_FALSE(isWholeNumber(bad)) << "'" << bad << "'";
}
