#pragma once
// Waiting for a neighbouring layer of the pair loop. The usual wait is short (a neighbour finishing its last
// cells), so it starts as a spin with the pause hint, which lets the sibling hyper-thread run. But on a shared
// machine the thread waited for may have lost its core to another process; spinning on then takes the core
// that thread needs next. So after a short spin the waiter yields, and after a longer one it sleeps in naps,
// each short against a scheduler's time slice.
#include <chrono>
#include <thread>

namespace dpdrng::dpd {

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
  __asm__ __volatile__("yield");
#endif
}

// Returns once ready() holds. The phases are timed rather than counted: a pause takes ~10 cycles on some CPUs
// and ~140 on others.
template <class Ready>
void wait_until(Ready&& ready) {
  using clock = std::chrono::steady_clock;
  constexpr auto kSpin = std::chrono::microseconds(20), kYield = std::chrono::microseconds(200);
  constexpr auto kNap = std::chrono::microseconds(50);
  const auto t0 = clock::now();
  for (;;) {
    for (int i = 0; i < 32; ++i) {
      if (ready()) return;
      cpu_relax();
    }
    const auto waited = clock::now() - t0;
    if (waited < kSpin) continue;
    if (waited < kYield)
      std::this_thread::yield();
    else
      std::this_thread::sleep_for(kNap);
  }
}

}  // namespace dpdrng::dpd
