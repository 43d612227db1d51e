// Linked into every harness. libFuzzer calls this once before the first input: the libraries' error handling as
// the CLI sets it (GSL's handler off, HDF5's stack printing off), so that a harness sees what a user of the CLI
// would.
#include "dpdrng/study/library_init.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  dpdrng::study::init_libraries();
  return 0;
}
