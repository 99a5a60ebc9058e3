#include "game/bench/machine.h"

#include "physics/cpu_features.h"

#include <fstream>
#include <sstream>
#include <thread>

namespace game::bench {

std::string Machine::describe() const {
    std::string s = cpu.empty() ? "unknown processor" : cpu;
    if (logical > 0) s += ", " + std::to_string(logical) + " logical CPUs";
    s += avx2 ? ", AVX2 lanes" : ", no AVX2 (one row at a time)";
    return s;
}

std::string parseCpuModel(const std::string& cpuinfo) {
    std::istringstream in(cpuinfo);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        const auto first = line.find_first_not_of(" \t", colon + 1);
        if (first == std::string::npos) return {};
        const auto last = line.find_last_not_of(" \t\r");
        return line.substr(first, last - first + 1);
    }
    return {};
}

Machine thisMachine() {
    Machine m;
    std::ifstream f("/proc/cpuinfo");
    std::ostringstream text;
    text << f.rdbuf();
    m.cpu = parseCpuModel(text.str());
    m.logical = std::thread::hardware_concurrency();
    m.avx2 = phys::processorHasAvx2();
    return m;
}

} // namespace game::bench
