// A vertex and a fragment shader ported together must still link, as a
// browser links them into one program.
#pragma once

#include <vector>

#include "driver/port/port_file.h"

namespace shaderport::driver {

// Pairs results whose inputs share a directory and a name (`ssao.vert` with
// `ssao.frag`), links each ported pair with glslang, and reports a pair that
// does not link as `port/stages-do-not-link` on the fragment shader.
// Returns how many pairs were linked.
size_t LinkPortedPairs(std::vector<PortResult>& results);

}  // namespace shaderport::driver
