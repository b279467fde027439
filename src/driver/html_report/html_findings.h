// A step's findings in the HTML page, with compiler cascades folded: after a
// compiler's first error in a file, the rest of its errors there are mostly echoes
// of it, so they go into a closed <details> under that first error.
#pragma once

#include <string>
#include <vector>

#include "driver/html_report/html_report.h"

namespace shaderport::driver {

// The `<pre>` blocks (escaped) and `<details class="cascade">` elements of `findings`.
// A finding with an empty `cascade` is shown where it is. The first finding of each
// non-empty `cascade` key is shown where it is, followed by a <details> holding every
// later finding with that key ("+N more errors"); those are not shown elsewhere.
void AppendFindings(std::string& out, const std::vector<ReportFinding>& findings);

}  // namespace shaderport::driver
