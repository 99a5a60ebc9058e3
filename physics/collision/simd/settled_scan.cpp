#include "physics/collision/simd/settled_scan.h"

#include "physics/cpu_features.h"

#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_SETTLED_SCAN_AVX2 1
#endif

namespace phys {

#if defined(ARTILLERY_SETTLED_SCAN_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {

// Four doubles' bits equal to four others', as a mask of 64-bit lanes.
inline __m256i sameBits4(const double* a, const double* b) {
    return _mm256_cmpeq_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(a)),
                              _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b)));
}

std::size_t skipSettledAvx2(const SettledRecords& r, std::size_t i, std::size_t n,
                            std::uint32_t alive, std::uint32_t sleeping, std::uint8_t* activeMark,
                            std::size_t& asleep) {
    const __m128i aliveBit = _mm_set1_epi32(static_cast<int>(alive));
    const __m128i sleepingBit = _mm_set1_epi32(static_cast<int>(sleeping));
    const __m256i zero = _mm256_setzero_si256();
    for (; i + 4 <= n; i += 4) {
        const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r.flags + i));
        const __m128i recorded =
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(r.settledFlags + i));
        const __m128i dead = _mm_cmpeq_epi32(_mm_and_si128(f, aliveBit), _mm_setzero_si128());
        const __m128i asleepNow = _mm_cmpeq_epi32(_mm_and_si128(f, sleepingBit), sleepingBit);
        const __m128i sameFlags = _mm_cmpeq_epi32(f, recorded);
        // Velocity +0: both components' bits zero (a -0 does not rest).
        const __m256i still = _mm256_and_si256(
            _mm256_cmpeq_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(r.vx + i)),
                               zero),
            _mm256_cmpeq_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(r.vy + i)),
                               zero));
        const __m256i rests = _mm256_or_si256(
            _mm256_cvtepi32_epi64(dead), _mm256_and_si256(_mm256_cvtepi32_epi64(asleepNow), still));
        const __m256i place =
            _mm256_and_si256(_mm256_and_si256(sameBits4(r.px + i, r.settledX + i),
                                              sameBits4(r.py + i, r.settledY + i)),
                             sameBits4(r.radius + i, r.settledRadius + i));
        const __m256i settled =
            _mm256_and_si256(_mm256_and_si256(rests, place), _mm256_cvtepi32_epi64(sameFlags));
        const unsigned lanes =
            static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(settled)));
        const unsigned aliveLanes =
            static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(dead))) ^ 0xFu;
        if (lanes == 0xFu) {
            std::memset(activeMark + i, 0, 4);
            asleep += static_cast<std::size_t>(__builtin_popcount(aliveLanes));
            continue;
        }
        // The settled lanes before the first that is not.
        const unsigned first = static_cast<unsigned>(__builtin_ctz(~lanes));
        for (unsigned k = 0; k < first; ++k)
            activeMark[i + k] = 0;
        asleep += static_cast<std::size_t>(__builtin_popcount(aliveLanes & ((1u << first) - 1u)));
        return i + first;
    }
    return i;
}

} // namespace
#pragma GCC pop_options
#endif

bool skipSettledInLanes() {
#if defined(ARTILLERY_SETTLED_SCAN_AVX2)
    return processorHasAvx2();
#else
    return false;
#endif
}

std::size_t skipSettled(const SettledRecords& r, std::size_t i, std::size_t n, std::uint32_t alive,
                        std::uint32_t sleeping, std::uint8_t* activeMark, std::size_t& asleep) {
#if defined(ARTILLERY_SETTLED_SCAN_AVX2)
    if (skipSettledInLanes()) return skipSettledAvx2(r, i, n, alive, sleeping, activeMark, asleep);
#endif
    (void)r, (void)n, (void)alive, (void)sleeping, (void)activeMark, (void)asleep;
    return i;
}

} // namespace phys
