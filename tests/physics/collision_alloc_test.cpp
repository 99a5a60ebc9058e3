// No allocation per step: once its buffers are warm, World::step
// with collisions, the broad phase, resting contact, sleep and rods allocates nothing,
// except that a buffer meeting a new peak (more contacts, or grid cells, than ever
// before) grows geometrically: a handful of times in a world's life, never per step.
// The global operator new of this test binary counts allocations while `counting` is set.
#include "physics/world.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
} // namespace

// These replace the global allocation functions, so malloc/free is the matching pair;
// GCC cannot see that through the replacement and warns (with -O2 and sanitizers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
    if (counting.load(std::memory_order_relaxed))
        allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
// The nothrow form too (std::stable_partition's temporary buffer uses it): left to the
// sanitizer's own operator new, its block would come back through the free() above and
// AddressSanitizer would report an alloc-dealloc mismatch in any test of this binary.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    if (counting.load(std::memory_order_relaxed))
        allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(n ? n : 1);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
#pragma GCC diagnostic pop

using namespace phys;

TEST(CollisionAllocation, SteppingAWarmWorldAllocatesNothing) {
    for (const BroadPhase bp : {BroadPhase::Grid, BroadPhase::SortAndSweep}) {
        WorldDef d;
        d.collision.broadPhase = bp;
        World w(d);
        w.shapes.addSegment({-5.0, 0.0}, {5.0, 0.0}, material::kFloor);
        w.shapes.addSegment({-5.0, 0.0}, {-5.0, 10.0}, material::kFloor);
        w.shapes.addSegment({5.0, 0.0}, {5.0, 10.0}, material::kFloor);
        w.shapes.addCircle({0.0, 2.0}, 0.7);
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> x(-4.5, 4.5), y(0.5, 8.0), v(-3.0, 3.0);
        for (int i = 0; i < 60; ++i) {
            ParticleDef pd;
            pd.position = {x(rng), y(rng)};
            pd.velocity = {v(rng), v(rng)};
            pd.radius = 0.05;
            pd.material = material::kTennis;
            w.particles.add(pd);
        }
        ParticleDef bead;
        bead.radius = 0.02;
        ParticleId prev = kNoParticle;
        for (int i = 0; i < 5; ++i) {
            bead.position = {-3.0 + 0.1 * (i + 1), 9.0};
            const auto id = w.particles.add(bead);
            w.constraints.push_back({ConstraintKind::Rod, id, prev, {-3.0, 9.0}, 0.1});
            prev = id;
        }
        for (int i = 0; i < 600; ++i)
            w.step(); // warm: buffers reach their working size
        allocations = 0;
        counting = true;
        for (int i = 0; i < 600; ++i)
            w.step();
        counting = false;
        // A few buffers may still reach a new peak here (the particle grid grows with the
        // busiest moment so far; static shapes sit in their own index, sized once).
        EXPECT_LE(allocations.load(), 4) << broadPhaseName(bp);
        const long first = allocations.load();
        // The next 600 steps (the simulation is deterministic): none at all.
        counting = true;
        allocations = 0;
        for (int i = 0; i < 600; ++i)
            w.step();
        counting = false;
        EXPECT_EQ(allocations.load(), 0) << broadPhaseName(bp);
        std::printf("%s: allocations in 600 warm steps: %ld, in the next 600: %ld\n",
                    broadPhaseName(bp), first, allocations.load());
        EXPECT_GT(w.collisionStats().passes, 0);
    }
}
