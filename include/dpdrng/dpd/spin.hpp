#pragma once
// A spin-wait hint for the pair loop's layer queue: it lets the sibling hyper-thread run and saves power while a
// thread waits for a neighbouring layer. Where the target has no such instruction the wait is a plain spin.
namespace dpdrng::dpd {

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
  __asm__ __volatile__("yield");
#endif
}

}  // namespace dpdrng::dpd
