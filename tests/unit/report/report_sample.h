// A small hand-built CheckReport that exercises every feature of the output
// formats: two checked files and a ShaderToy Common file, errors, warnings, a
// note, fix-its, a multi-byte UTF-8 line and a tab.
#pragma once

#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::testing {

struct ReportSample {
  SourceManager sources;
  CheckReport report;
  ReportOptions options;

  ReportSample();
};

}  // namespace shaderport::testing
