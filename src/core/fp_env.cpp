#include "rtpro/core/fp_env.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

namespace rtpro {

void set_tracing_fp_mode() {
  _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
  _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

}  // namespace rtpro
