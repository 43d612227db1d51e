#include "dpdrng/study/library_init.hpp"

#include <hdf5.h>

#include "dpdrng/stats/library_init.hpp"

namespace dpdrng::study {

void init_libraries() {
  stats::init_gsl();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

}  // namespace dpdrng::study
