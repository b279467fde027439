#include "allocator_name.h"

#ifdef SHADERPORT_MIMALLOC
#include <mimalloc.h>
#endif

namespace shaderport::cli {

std::string AllocatorName() {
#ifdef SHADERPORT_MIMALLOC
  const int version = mi_version();  // 209 for 2.0.9
  return "mimalloc " + std::to_string(version / 100) + "." + std::to_string(version / 10 % 10) +
         "." + std::to_string(version % 10);
#else
  return "system malloc";
#endif
}

}  // namespace shaderport::cli
