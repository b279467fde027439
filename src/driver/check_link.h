// `check` of whole programs: a vertex and a fragment shader with the same stem in
// the same directory (or given with --link) are linked as a browser links a WebGL
// program, by the rules of rules/webgl/program_link.h.
#pragma once

#include <vector>

#include "driver/check_file.h"

namespace shaderport::driver {

// Pairs of job indices (vertex, fragment) that form programs.
std::vector<std::pair<size_t, size_t>> FindPrograms(const std::vector<FileJob>& jobs,
                                                    const CheckOptions& options);

// Adds the link findings to the two reports; only when both stages are error-free.
void LinkProgram(const FileJob& vertex_job, const FileJob& fragment_job,
                 const CheckOptions& options, SourceManager& sources, FileReport& vertex,
                 FileReport& fragment);

}  // namespace shaderport::driver
