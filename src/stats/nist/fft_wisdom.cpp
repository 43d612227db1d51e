// The spectral test's FFTW plan for 2^20 bits (SP800-22's recommended sequence length), as FFTW's wisdom.
// Planned with FFTW_PATIENT by `dpdrng bench nist --fft-wisdom` (FFTW 3.3.10, Debian's libfftw3) on an AMD EPYC
// (Zen 4): a transform of AVX codelets that runs in ≈ 3.5 ms there, against ≈ 5.7 ms for FFTW_ESTIMATE's plan.
// Where FFTW cannot use it (another FFTW version, a CPU without AVX) the test plans with FFTW_ESTIMATE; which
// plan ran does not change a count (spectral_peaks_below).
#include "fft_wisdom.hpp"

namespace dpdrng::stats::nist::detail {

const char* const kFftWisdom =
    "(fftw-3.3.10 fftw_wisdom #x458a31c8 #x92381c4c #x4f974889 #xcd46f97e\n"
    "  (fftw_dft_vrank_geq1_register 0 #x10048 #x10048 #x0 #x63d9ded6 #xd9f3f1e7 #xf0c7129f #x4f86536f)\n"
    "  (fftw_rdft_rank0_register 3 #x11048 #x11048 #x0 #x1641aee8 #x68348156 #x2fe7d5f1 #x75632f19)\n"
    "  (fftw_dft_vrank_geq1_register 0 #x10048 #x10048 #x0 #xcbfbaa93 #x8a8e94ef #x81a9a4d1 #x8a7dd6bc)\n"
    "  (fftw_dft_nop_register 0 #x11048 #x11048 #x0 #xd5f1144f #x093bb794 #x81390dfb #xfae7a255)\n"
    "  (fftw_codelet_t2fv_8_avx 0 #x10048 #x10048 #x0 #x805e4660 #x4265e91d #x92a303bd #xb22aef96)\n"
    "  (fftw_codelet_r2cfII_2 2 #x11048 #x11048 #x0 #xa696229f #x39db7cd9 #x20f2c081 #x5e035934)\n"
    "  (fftw_codelet_hc2cfdftv_2_avx 0 #x11048 #x11048 #x0 #xea52e625 #x20db9f08 #xfaf2d59a #x016c62ec)\n"
    "  (fftw_codelet_q1fv_8_avx 0 #x11048 #x11048 #x0 #x786686d1 #x4f2b4902 #x1a102bbc #x3881ee2f)\n"
    "  (fftw_dft_vrank_geq1_register 0 #x11048 #x11048 #x0 #x17a1c9d3 #xd98f6ec5 #x9ac26888 #xf8366cc7)\n"
    "  (fftw_codelet_t3fv_8_avx 0 #x11048 #x11048 #x0 #x55ff8eea #x0f11be95 #x4cfe6152 #xa6b4965b)\n"
    "  (fftw_codelet_t3fv_8_avx 0 #x10048 #x10048 #x0 #xa4170240 #xb92a3dfd #x3ed28145 #xd923518c)\n"
    "  (fftw_dft_r2hc_register 0 #x11048 #x11048 #x0 #x95dfcba2 #x1c879d3c #x881435fc #xe445c1cd)\n"
    "  (fftw_codelet_r2cf_2 2 #x11048 #x11048 #x0 #xbda659ee #x29122012 #xd165f789 #xe7c4640a)\n"
    "  (fftw_dft_vrank_geq1_register 0 #x10048 #x10048 #x0 #x8cadd2f4 #x627ae513 #xc1926d68 #xfe75a816)\n"
    "  (fftw_dft_buffered_register 0 #x11048 #x11048 #x0 #x3e1c64d4 #x31d82ab3 #xf698ae40 #x5b6f8c7a)\n"
    "  (fftw_codelet_t2fv_16_avx 0 #x10048 #x10048 #x0 #xb0729814 #x9e96a1da #x50fde173 #xd7b9dffe)\n"
    "  (fftw_codelet_n2fv_8_avx 0 #x10048 #x10048 #x0 #x32608a55 #xaf58e1fd #x02b1b8d7 #x5a0aa8a6)\n"
    ")\n";

}  // namespace dpdrng::stats::nist::detail
