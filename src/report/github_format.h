// GitHub Actions workflow commands, one annotation per diagnostic:
//   ::error file=a.frag,line=3,col=5,endLine=3,endColumn=9,title=rule/id::message
#pragma once

#include <string>
#include <string_view>

#include "report/check_report.h"

namespace shaderport {

std::string FormatGithub(const CheckReport& report, const ReportOptions& options);

// Escaping of a command's message: '%', '\r', '\n'.
std::string EscapeGithubData(std::string_view text);
// Escaping of a property value: the message escapes plus ':' and ','.
std::string EscapeGithubProperty(std::string_view text);

}  // namespace shaderport
