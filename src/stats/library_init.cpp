#include "dpdrng/stats/library_init.hpp"

#include <gsl/gsl_errno.h>

namespace dpdrng::stats {

void init_gsl() { gsl_set_error_handler_off(); }

}  // namespace dpdrng::stats
