// The human format, as clang prints diagnostics:
//
//   shader.frag:14:5: error: 'gl_FragColor' does not exist in GLSL ES 3.00 [rule/id]
//      14 |     gl_FragColor = vec4(col, 1.0);
//         |     ^~~~~~~~~~~~
//     fix-it: replace 'gl_FragColor' with 'fragColor'
//
// then notes the same way, and one summary line at the end.
#pragma once

#include <string>

#include "report/check_report.h"

namespace shaderport {

std::string FormatText(const CheckReport& report, const ReportOptions& options);

// "2 errors, 1 warning in 1 file (3 files checked)"
std::string SummaryLine(const ReportSummary& summary);

// "[*] N fixable with 'shaderport fix'" when some finding carries a safe fix.
std::string FixableLine(const ReportSummary& summary);

}  // namespace shaderport
