// What the processor the program runs on can do, for the loops that have a path for it and
// pick it at run time (the build targets plain x86-64).
#pragma once

namespace phys {

/// This processor runs AVX2 instructions (asked once). False where that cannot be asked.
bool processorHasAvx2();

} // namespace phys
