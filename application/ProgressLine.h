// SPDX-License-Identifier: BSD-3-Clause
// The tool's one way of printing the progress of long work (propagation, final gather,
// hallucination) on stderr: on a terminal one line rewritten in place ("tracing subfields 40%");
// in a log or a pipe the steps appended to one line ("tracing subfields 0% 10% ... 100%"), since
// a carriage return there only garbles the log. Anything printed while such a line may be open
// calls EndProgressLine first, so results never run into the progress text.
#ifndef mesolight_ProgressLine_h
#define mesolight_ProgressLine_h

#include "Progress.h"

#include <string>

namespace mesolight
{

/** A callback printing `what` and the fraction done in steps of 10%; it never aborts. */
ProgressCallback PrintedProgress(const std::string& what);

/** Ends an open progress line (erases it on a terminal), so the next output starts a line. */
void EndProgressLine();

} // namespace mesolight

#endif
