// SPDX-License-Identifier: BSD-3-Clause
// The `mesolight` tool's commands as one table: each command's name, usage, one-line summary and
// handler, or a nested table (`mesolight bench <what>`, `mesolight vlf <what>`). Dispatch and the
// top-level help are written once, here, from the table.
#ifndef mesolight_CommandTable_h
#define mesolight_CommandTable_h

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace mesolight
{

struct Command
{
  /** The word that selects it; "" for a group's default (`mesolight bench [options]`). */
  std::string Name;
  /** What follows the command words in its usage line, e.g. "DEPTH_IMAGE --out FILE [options]". */
  std::string Usage;
  /** One line in `mesolight --help` (wrapped with '\n' where it is long). */
  std::string Summary;
  /** Runs the command on the arguments after its words; returns the exit code. */
  std::function<int(const std::vector<std::string>&)> Run;
  /** A group's commands (`bench`, `vlf`): selected by the next word. */
  std::vector<Command> Subcommands;
};

/**
 * Runs the command args select from table. prefix is the words so far ("mesolight",
 * "mesolight vlf"). Without a command word: the group's default command, else the group's usage
 * (exit 0 on --help / -h, 2 without arguments); an unknown word is a usage error (exit 2).
 */
int DispatchCommand(const std::string& prefix, const std::vector<Command>& table,
  const std::vector<std::string>& args);

/** The usage lines and summaries of every command in table, in two columns. */
void PrintCommandUsage(
  std::ostream& os, const std::string& prefix, const std::vector<Command>& table);

} // namespace mesolight

#endif
