// ShaderToy projects in `check`: a JSON document becomes one job per pass, each
// compiled as the site compiles that tab (Common first, the tab's main(), the
// sampler types of its inputs).
#pragma once

#include <deque>
#include <filesystem>
#include <vector>

#include "driver/check_file.h"
#include "driver/project/json_project_reader.h"
#include "report/check_report.h"

namespace shaderport::driver {

// .json and .jsonl files are read as projects.
bool IsProjectDocument(const std::filesystem::path& path);

// Reads `base.path` and appends a job per pass (copies of `base` with the pass's
// source, tab and channels); problems with the document become `problems`. The
// projects are kept in `documents`, which must outlive the jobs.
void AddProjectJobs(const FileJob& base, SourceManager& sources,
                    std::deque<project::ProjectDocument>& documents, std::vector<FileJob>& jobs,
                    std::vector<FileReport>& problems);

// A file of a project folder (a tab file beside shadertoy.toml): its tab and the
// sampler types of the manifest's channels; false for any other file.
bool ApplyFolderTab(FileJob& job);

}  // namespace shaderport::driver
