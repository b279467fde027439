// Which findings of a check `shaderport fix` repairs. check runs fix on the file as
// it decided the file (fix mode, validated as the host composes it); a finding that
// is gone from fix's result gets the safe fix-its of the rule findings fix applied
// on it (or else on its line), each used once, so that every output format can mark
// it fixable (text `[*]`, JSON `fixable`, SARIF `fixes`) and an editor can apply it.
#pragma once

#include "diag/diagnostic.h"
#include "driver/file_decision.h"
#include "driver/front_end.h"
#include "driver/port/port_file.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// The fix-mode options that read a file as `decision` says it is.
PortOptions FixOptionsFor(const FileDecision& decision);

// Whether `fix` has anything to do on the file as check's front end read it: some
// rule of fix mode offers a safe fix. No glslang: check runs fix only when it does.
bool FixOffersAnEdit(const SourceFile& file, const FrontEndResult& front,
                     const FileDecision& decision);

// Whether AttachRepairs could give `findings` anything: some finding in a file carries
// no safe fix of its own. Without one, check need not run fix at all.
bool AnyFindingWithoutFix(const DiagnosticList& findings);

// Attaches to `findings` (check's, located in the original files) the fixes of the
// findings `fixed` repaired. Findings that already carry a safe fix are left alone.
void AttachRepairs(const PortResult& fixed, const SourceManager& sources, DiagnosticList& findings);

}  // namespace shaderport::driver
