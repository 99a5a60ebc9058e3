// Floating-point exceptions trapped in the physics tests: with
// ARTILLERY_TRAP_FP set (make sanitize sets it), every physics test runs with invalid
// operations, division by zero and overflow raising SIGFPE, so a NaN or infinity born
// anywhere in the physics stops the test at the line that made it.
//
// Test suites that drive a method past its stability limit on purpose (the energy
// growth is the point of the test) run without the trap; the guard's tests are among
// them because they feed it NaN and infinity to remove.
#include <gtest/gtest.h>

#include <cfenv>
#include <cstdlib>
#include <string>

namespace {

constexpr int kTrapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

bool explodesOnPurpose(const std::string& suite) {
    for (const char* s : {"SpringEnergy", "Guard", "ImplicitEuler", "Stability"})
        if (suite == s) return true;
    return false;
}

class FpTrap : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo& test) override {
        std::feclearexcept(FE_ALL_EXCEPT);
        if (!explodesOnPurpose(test.test_suite_name())) feenableexcept(kTrapped);
    }
    void OnTestEnd(const ::testing::TestInfo&) override {
        fedisableexcept(kTrapped);
        std::feclearexcept(FE_ALL_EXCEPT);
    }
};

// Registered before main() runs (gtest_main only initialises and runs the tests).
const bool kInstalled = [] {
    if (std::getenv("ARTILLERY_TRAP_FP"))
        ::testing::UnitTest::GetInstance()->listeners().Append(new FpTrap);
    return true;
}();

} // namespace
