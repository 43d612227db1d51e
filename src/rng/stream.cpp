#include "dpdrng/rng/stream.hpp"

namespace dpdrng::rng {

namespace {
template <class G>
void fill_hash(const G& g, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out) {
  constexpr std::uint64_t W = G::kWords;
  std::size_t k = 0;
  std::uint64_t call = offset / W;
  if (offset % W != 0) {  // resume inside a call
    const auto b = g.stream(start, call++);
    for (std::uint64_t w = offset % W; w < W && k < out.size(); ++w) out[k++] = b[w];
  }
  // Whole calls in a tight loop: with a compile-time round count this vectorises.
  const std::size_t whole = (out.size() - k) / W;
  for (std::size_t c = 0; c < whole; ++c) {
    const auto b = g.stream(start, call + c);
    for (std::uint64_t w = 0; w < W; ++w) out[k + c * W + w] = b[w];
  }
  k += whole * W;
  call += whole;
  if (k < out.size()) {
    const auto b = g.stream(start, call);
    for (std::uint64_t w = 0; k < out.size(); ++w) out[k++] = b[w];
  }
}
}  // namespace

int words_per_call(const GeneratorSpec& spec) {
  if (spec.name == "mt19937") return 1;
  return with_hash(spec, [](const auto& g) { return std::decay_t<decltype(g)>::kWords; });
}

void fill_stream(const GeneratorSpec& spec, std::uint64_t start, std::uint64_t offset, std::span<std::uint64_t> out) {
  if (spec.name == "mt19937") {
    Mt19937 mt(start);
    mt.engine.discard(2 * offset);
    for (auto& w : out) w = mt.next64();
    return;
  }
  with_hash(spec, [&](const auto& g) { fill_hash(g, start, offset, out); });
}

}  // namespace dpdrng::rng
