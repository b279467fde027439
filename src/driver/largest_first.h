// The order in which `check -j N` hands files out: largest first.
#pragma once

#include <cstddef>
#include <vector>

#include "driver/check_file.h"

namespace shaderport::driver {

// The indices of `jobs` by decreasing size in bytes, ties in input order. The size is
// what is known without reading: a project pass's text, text given in memory, else the
// file's size on disk (0 when it cannot be had: the file is then handed out last, and
// CheckFile reports why it cannot be read). Sizes stand in for the work a file costs:
// given out in input order, one large file near the end of a batch runs alone at the
// end while the other jobs are done (bench/parallel_scaling_sim.py).
std::vector<size_t> LargestFirst(const std::vector<FileJob>& jobs);

}  // namespace shaderport::driver
