// The machine a figure was taken on. The same code's lead over Box2D moves by a quarter
// from one processor to another (the particles' solver waits on arithmetic, Box2D's step
// on memory), so a figure without its machine cannot be compared with another.
#pragma once

#include <string>

namespace game::bench {

struct Machine {
    std::string cpu;      ///< the processor's model name, "" where the system does not say
    unsigned logical = 0; ///< logical processors the program may run on (0: unknown)
    bool avx2 = false;    ///< the solver's four-lane paths run (phys::processorHasAvx2)
    /// "Intel(R) Xeon(R) Processor @ 2.50GHz, 2 logical CPUs, AVX2 lanes".
    std::string describe() const;
};

/// This machine: /proc/cpuinfo's model name, the logical processors, AVX2.
Machine thisMachine();

/// The first "model name" of /proc/cpuinfo's text, spaces trimmed; "" if none.
std::string parseCpuModel(const std::string& cpuinfo);

} // namespace game::bench
