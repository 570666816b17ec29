// SPDX-License-Identifier: BSD-3-Clause
// The one check every `mesolight` command makes on a file it is about to write, before any work:
// a user's input is never overwritten (not by the same name, nor through a symbolic or hard
// link), and a missing or read-only directory is reported up front instead of after a long run.
#ifndef mesolight_OutputFile_h
#define mesolight_OutputFile_h

#include <string>
#include <vector>

namespace mesolight
{

/** Whether two paths name the same existing file (device and inode, so through links too). */
bool SameFile(const std::string& a, const std::string& b);

/**
 * Returns "" when `out` may be written, else why not (one line naming the file): `out` is empty,
 * equals one of `inputs` (empty entries are ignored; pass the command's other outputs too), its
 * directory is missing or not writable, or it exists and is not a writable regular file.
 */
std::string CheckOutputFile(const std::string& out, const std::vector<std::string>& inputs);

class CommandLine;
/**
 * CheckOutputFile for each of the output options `names` the command was given, against the
 * inputs and the command's other outputs; "" when all may be written, else "--csv: why".
 */
std::string CheckOutputOptions(
  const CommandLine& cl, const std::vector<std::string>& names, std::vector<std::string> inputs);

/** Whether `file` ends in `extension` (with its dot, e.g. ".png"), compared without case. */
bool HasExtension(const std::string& file, const std::string& extension);

/**
 * "" when none of the options `names` was given, or each names a file ending in one of
 * `extensions` (with the dot, compared without case), else "--out: 'r.exr' does not end in .png: "
 * followed by `advice`. A writer picks its format by the command, not by the name: a PNG written
 * as r.exr, or a relief texture as a JPEG (no alpha: the depth lost), would be found out later.
 */
std::string CheckOutputExtension(const CommandLine& cl, const std::vector<std::string>& names,
  const std::vector<std::string>& extensions, const std::string& advice);

/** CheckOutputExtension for the commands that render: --out a .png (the display image), --exr
 *  and --relief-mask .exr (linear). */
std::string CheckImageOutputNames(const CommandLine& cl);

} // namespace mesolight

#endif
