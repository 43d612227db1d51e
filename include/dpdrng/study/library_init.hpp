#pragma once
// The error handling of the libraries under the study layer, set once at program start (the CLI's main, the
// test suite's environment, a fuzz harness's initialiser): GSL's aborting handler off (stats::init_gsl), and
// HDF5's printing of its error stack off, since every HDF5 call is checked and reported as our own message.

namespace dpdrng::study {

void init_libraries();

}  // namespace dpdrng::study
