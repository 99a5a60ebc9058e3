// The settled sleepers of AwakeSet::select (awake_set.h), skipped four slots at a time.
//
// Each sub-step the awake set tests every slot: a slot is settled when it is empty or
// asleep at rest (velocity +0), and its flags, place and radius are the ones recorded
// when a sub-step last worked on it, bit for bit. In a pile that has mostly fallen asleep
// nearly every slot passes, and the test, a dozen loads and branches a slot, ran over
// every slot of such a tick. skipSettled runs the same test on four slots at a time with AVX2 where
// the processor has it: integer comparisons of the flags and of the doubles' bits, so it
// passes exactly the slots the one-slot test passes, and stops at the first slot that
// does not pass, for the awake set to take that slot itself.
#pragma once

#include <cstddef>
#include <cstdint>

namespace phys {

/// What the test reads: the particles' flags, velocities, places and radii, and the
/// records (flags, place, radius) of the sub-step that last worked on each slot.
struct SettledRecords {
    const std::uint32_t* flags;
    const double *vx, *vy, *px, *py, *radius;
    const std::uint32_t* settledFlags;
    const double *settledX, *settledY, *settledRadius;
};

/// From slot i, the slots before n that are settled, in groups of four where the processor
/// has AVX2 (none without): each gets activeMark 0, and those alive count into asleep.
/// Returns the first slot that is not settled, or the first of the tail shorter than four,
/// for the caller to test one slot at a time.
std::size_t skipSettled(const SettledRecords& r, std::size_t i, std::size_t n, std::uint32_t alive,
                        std::uint32_t sleeping, std::uint8_t* activeMark, std::size_t& asleep);

/// skipSettled takes groups of four here (AVX2 compiled in, and the processor has it).
bool skipSettledInLanes();

} // namespace phys
