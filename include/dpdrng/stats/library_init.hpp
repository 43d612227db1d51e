#pragma once
// GSL's default error handler aborts the process. Every GSL call in this layer uses an _e variant or checks the
// status it returns, so a program that uses stats turns the handler off once, before any test runs: the CLI's
// main through study::init_libraries(), the test suite through its GoogleTest environment.

namespace dpdrng::stats {

void init_gsl();

}  // namespace dpdrng::stats
