// SARIF 2.1.0 as GitHub code scanning reads it: one run, the rules used with their
// catalog text, results with UTF-16 regions, notes as related locations and
// fix-its as fixes. Deterministic: no timestamps, rules sorted by id.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/check_report.h"

namespace shaderport {

inline constexpr const char* kSarifSchemaUri = "https://json.schemastore.org/sarif-2.1.0.json";
// The base id that relative artifact URIs are resolved against.
inline constexpr const char* kSarifSourceRoot = "%SRCROOT%";

nlohmann::ordered_json ReportToSarif(const CheckReport& report, const ReportOptions& options);

std::string FormatSarif(const CheckReport& report, const ReportOptions& options);

}  // namespace shaderport
