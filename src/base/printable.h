// Text from files (names, JSON pass names, config keys, suppression ids) made safe
// to print on a terminal: a control character could move the cursor, recolour the
// screen or, as a newline in a pass name, forge a line of output that looks like a
// finding. JSON and SARIF escape them already; text output uses these.
#pragma once

#include <string>
#include <string_view>

namespace shaderport {

// Each control character escaped: \n \r \t, \xHH for the other C0 bytes and DEL,
// \u0080..\u009f for the C1 controls (a UTF-8 "\xC2\x9B" is CSI to some terminals).
// Other bytes, valid UTF-8 or not, are kept.
std::string EscapeControlCharacters(std::string_view text);

// As EscapeControlCharacters, but a line break becomes a space: for messages, which
// may be wrapped by the tool that wrote them but must stay one line of output.
std::string OneLinePrintable(std::string_view text);

}  // namespace shaderport
