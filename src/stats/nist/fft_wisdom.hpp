#pragma once
// The spectral test's shipped FFTW plan (fft_wisdom.cpp): internal to the SP800-22 tests.

namespace dpdrng::stats::nist::detail {

extern const char* const kFftWisdom;

}  // namespace dpdrng::stats::nist::detail
