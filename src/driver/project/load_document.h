// Reading a ShaderToy JSON document for a command: the file registered in the
// SourceManager and its problems as input/* diagnostics on it.
#pragma once

#include <filesystem>
#include <memory>

#include "diag/diagnostic.h"
#include "driver/project/json_project_reader.h"
#include "driver/read_input.h"
#include "source/source_manager.h"

namespace shaderport::driver::project {

struct LoadedDocument {
  const SourceFile* document = nullptr;  // the text as read ("" when unreadable)
  std::unique_ptr<ProjectDocument> read = std::make_unique<ProjectDocument>();
  DiagnosticList problems;  // unreadable, invalid, or no project in it

  bool Usable() const { return problems.empty(); }
};

// .jsonl is read line by line, anything else as one document.
LoadedDocument LoadDocument(const std::filesystem::path& path, InputText input,
                            SourceManager& sources);

}  // namespace shaderport::driver::project
