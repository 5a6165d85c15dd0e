// Issue 24, the physical limit: what one core of this machine can do, measured, for bench/physical_limit.sh.
// - the clock: a chain of dependent integer adds (one cycle each on every x86 core of the last 15 years);
// - the double-precision peak: 12 independent chains of 4-wide fused multiply-adds (AVX2/FMA, the copy
//   of the hot loops this processor runs: hot_path.h), and the same with scalar FMAs;
// - the latencies that bound a serial recursion: one dependent chain of FMAs, of divisions, of square roots;
// - a STREAM-like triad a[i] = b[i] + s c[i] on working sets in L2, in L3 and in memory (bytes counted as
//   STREAM does: 24 per element, the write-allocate's extra read of a[] not counted).
// One thread (the simulator steps on one). Built with the bench's flags (-O2 -fno-math-errno
// -fno-trapping-math); the kernels carry target("avx2,fma") as the hot path's x86-64-v3 copy does.
// Prints "key value" lines. Usage: machine_peak [seconds per kernel, default 0.3]
#include <immintrin.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Best of 5 of `kernel(iterations)`, iterations doubled until one run takes `seconds`: seconds per iteration.
template <class F>
double bestSecondsPerIteration(F kernel, double seconds) {
  long iterations = 1;
  for (;;) {
    const auto t0 = Clock::now();
    kernel(iterations);
    if (since(t0) > seconds) break;
    iterations *= 2;
  }
  double best = 1e30;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = Clock::now();
    kernel(iterations);
    best = std::min(best, since(t0) / iterations);
  }
  return best;
}

volatile double sink;  // keeps each kernel's result alive

/// 10 dependent adds an iteration: 10 cycles (the loop's own add and branch run beside them).
void integerChain(long iterations) {
  long x = 0;
  for (long i = 0; i < iterations; ++i) {
    asm volatile(
        "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\t"
        "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0"
        : "+r"(x));
  }
  sink = static_cast<double>(x);
}

/// 12 independent accumulators (named, so that they stay in registers): enough to cover an FMA's latency
/// (4 cycles) on both FMA pipes. T is __m256d (4 doubles) or __m128d used as a scalar.
#define CABLE_PEAK_BODY(FMA)                                                                     \
  for (long i = 0; i < iterations; ++i) {                                                        \
    a0 = FMA(a0, m, c); a1 = FMA(a1, m, c); a2 = FMA(a2, m, c); a3 = FMA(a3, m, c);              \
    a4 = FMA(a4, m, c); a5 = FMA(a5, m, c); a6 = FMA(a6, m, c); a7 = FMA(a7, m, c);              \
    a8 = FMA(a8, m, c); a9 = FMA(a9, m, c); a10 = FMA(a10, m, c); a11 = FMA(a11, m, c);          \
  }

/// 96 flops an iteration.
__attribute__((target("avx2,fma"))) void packedFma(long iterations) {
  // Distinct starts: equal ones would let the compiler compute one chain for all twelve.
  __m256d a0 = _mm256_set1_pd(1.0), a1 = _mm256_set1_pd(1.1), a2 = _mm256_set1_pd(1.2), a3 = _mm256_set1_pd(1.3),
          a4 = _mm256_set1_pd(1.4), a5 = _mm256_set1_pd(1.5), a6 = _mm256_set1_pd(1.6), a7 = _mm256_set1_pd(1.7),
          a8 = _mm256_set1_pd(1.8), a9 = _mm256_set1_pd(1.9), a10 = _mm256_set1_pd(2.0), a11 = _mm256_set1_pd(2.1);
  const __m256d m = _mm256_set1_pd(0.999999), c = _mm256_set1_pd(1e-6);
  CABLE_PEAK_BODY(_mm256_fmadd_pd)
  const __m256d s = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(a0, a1), _mm256_add_pd(a2, a3)),
                                  _mm256_add_pd(_mm256_add_pd(a4, a5), _mm256_add_pd(a6, a7)));
  sink = _mm256_cvtsd_f64(_mm256_add_pd(s, _mm256_add_pd(_mm256_add_pd(a8, a9), _mm256_add_pd(a10, a11))));
}

/// The same with one double per instruction: 24 flops an iteration.
__attribute__((target("avx2,fma"))) void scalarFma(long iterations) {
  __m128d a0 = _mm_set_sd(1.0), a1 = _mm_set_sd(1.1), a2 = _mm_set_sd(1.2), a3 = _mm_set_sd(1.3),
          a4 = _mm_set_sd(1.4), a5 = _mm_set_sd(1.5), a6 = _mm_set_sd(1.6), a7 = _mm_set_sd(1.7),
          a8 = _mm_set_sd(1.8), a9 = _mm_set_sd(1.9), a10 = _mm_set_sd(2.0), a11 = _mm_set_sd(2.1);
  const __m128d m = _mm_set_sd(0.999999), c = _mm_set_sd(1e-6);
  CABLE_PEAK_BODY(_mm_fmadd_sd)
  const __m128d s = _mm_add_sd(_mm_add_sd(_mm_add_sd(a0, a1), _mm_add_sd(a2, a3)),
                               _mm_add_sd(_mm_add_sd(a4, a5), _mm_add_sd(a6, a7)));
  sink = _mm_cvtsd_f64(_mm_add_sd(s, _mm_add_sd(_mm_add_sd(a8, a9), _mm_add_sd(a10, a11))));
}

/// One dependent chain each: seconds per iteration = the instruction's latency.
__attribute__((target("avx2,fma"))) void fmaChain(long iterations) {
  __m128d x = _mm_set_sd(1.0);
  const __m128d m = _mm_set_sd(0.999999), a = _mm_set_sd(1e-6);
  for (long i = 0; i < iterations; ++i) x = _mm_fmadd_sd(x, m, a);
  sink = _mm_cvtsd_f64(x);
}
__attribute__((target("avx2,fma"))) void divChain(long iterations) {
  __m128d x = _mm_set_sd(1.5);
  const __m128d d = _mm_set_sd(1.0000001);
  for (long i = 0; i < iterations; ++i) x = _mm_div_sd(x, d);
  sink = _mm_cvtsd_f64(x);
}
__attribute__((target("avx2,fma"))) void sqrtChain(long iterations) {
  __m128d x = _mm_set_sd(1.5);
  const __m128d one = _mm_set_sd(1.0);
  // sqrt(x) + 1 stays near 2.6: the chain's time is one square root and one add.
  for (long i = 0; i < iterations; ++i) x = _mm_add_sd(_mm_sqrt_sd(x, x), one);
  sink = _mm_cvtsd_f64(x);
}

/// The triad over n elements, `iterations` passes.
__attribute__((target("avx2,fma"))) void triad(double* __restrict a, const double* __restrict b,
                                               const double* __restrict c, long n, long iterations) {
  for (long it = 0; it < iterations; ++it) {
    for (long i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    asm volatile("" : : "r"(a) : "memory");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.3;
  const double per_add = bestSecondsPerIteration(integerChain, seconds) / 10.0;
  const double ghz = 1e-9 / per_add;
  std::printf("clock_ghz %.3f\n", ghz);
  const double packed = 96.0 / bestSecondsPerIteration(packedFma, seconds);
  std::printf("peak_avx2_fma_gflops %.2f\npeak_avx2_flop_per_cycle %.2f\n", packed * 1e-9, packed * per_add);
  const double scalar = 24.0 / bestSecondsPerIteration(scalarFma, seconds);
  std::printf("peak_scalar_fma_gflops %.2f\npeak_scalar_flop_per_cycle %.2f\n", scalar * 1e-9, scalar * per_add);
  std::printf("latency_fma_cycles %.2f\n", bestSecondsPerIteration(fmaChain, seconds) / per_add);
  std::printf("latency_div_cycles %.2f\n", bestSecondsPerIteration(divChain, seconds) / per_add);
  std::printf("latency_sqrt_plus_add_cycles %.2f\n", bestSecondsPerIteration(sqrtChain, seconds) / per_add);
  // Working sets (three arrays): 96 KiB (L2: 512 KiB a core), 6 MiB (L3), 384 MiB (memory).
  for (const long n : {4096L, 262144L, 16777216L}) {
    std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
    const double t = bestSecondsPerIteration([&](long it) { triad(a.data(), b.data(), c.data(), n, it); },
                                             seconds);
    std::printf("triad_gbs_%ldkib %.2f\n", 3 * n * 8 / 1024, 24.0 * n / t * 1e-9);
  }
  return 0;
}
