// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// A reference for the core's clock, to register in a benchmark program: a chain of dependent
// register-to-register integer additions, one cycle each on any out-of-order core of the last
// fifteen years (x86-64 and ARM alike), so that the time of another benchmark of the same run
// converts to cycles of the clock the core really ran at. The shared machines differ in clock
// between sessions, and within a session other guests' load slows the same code by up to 1.6x
// while this chain, which needs only one instruction per cycle, still reports the clock
// (2.87-2.96 GHz on 2026-12-02): times in cycles compare across machines, and their swings tell
// contention from clock (benchmark/README.md).
// The addend is a register the compiler cannot see through: Intel's Golden Cove cores (the Xeon
// of 2026-12-03) fold additions of an immediate at register renaming, and a chain of `x += 1`
// ran at 18-19 "GHz" there, 5.4x the 3.5 GHz of `x += y`.
#ifndef SHAPECORR_BENCHMARK_BENCH_CLOCK_H
#define SHAPECORR_BENCHMARK_BENCH_CLOCK_H

#include <benchmark/benchmark.h>

#include <cstdint>

namespace bench {

/// Additions per iteration of BM_Reference_ClockCycles.
constexpr std::int64_t kClockAdds = 1 << 20;

/// kClockAdds dependent additions per iteration, eight per loop trip (so that the loop's own
/// instructions run beside the chain, not on it); the empty asm statements keep the compiler
/// from folding them and hide the addend's value (an immediate could be folded by the core).
/// Its time per iteration is kClockAdds cycles: benchmark/ratios.py derives the effective clock
/// (counter `adds`) and each benchmark's cycles from it.
inline void BM_Reference_ClockCycles(benchmark::State& state) {
  std::uint64_t x = 0, one = 1;
  __asm__ volatile("" : "+r"(one)); // a register of unknown value, not an immediate
  for(auto _ : state) {
    for(std::int64_t i = 0; i < kClockAdds; i += 8) {
#define SHAPECORR_BENCH_ADD x += one; __asm__ volatile("" : "+r"(x));
      SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD
      SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD SHAPECORR_BENCH_ADD
#undef SHAPECORR_BENCH_ADD
    }
  }
  benchmark::DoNotOptimize(x);
  state.counters["adds"] = static_cast<double>(kClockAdds);
}

} // namespace bench

#endif
