// SPDX-License-Identifier: BSD-3-Clause
#include "CommandTable.h"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace mesolight
{
namespace
{
constexpr int UsageColumn = 45; // summaries start at column 2 + UsageColumn

void PrintGroupHelp(std::ostream& os, const std::string& prefix, const std::vector<Command>& table)
{
  os << "Usage:\n";
  PrintCommandUsage(os, prefix, table);
  os << "Run '" << prefix << " COMMAND --help' for the options of a command.\n";
}
} // namespace

void PrintCommandUsage(
  std::ostream& os, const std::string& prefix, const std::vector<Command>& table)
{
  for (const Command& command : table)
  {
    const std::string words = command.Name.empty() ? prefix : prefix + " " + command.Name;
    if (!command.Subcommands.empty())
    {
      PrintCommandUsage(os, words, command.Subcommands);
      continue;
    }
    const std::string usage = words + (command.Usage.empty() ? "" : " " + command.Usage);
    std::istringstream summary(command.Summary);
    std::string line;
    bool first = true;
    if (static_cast<int>(usage.size()) >= UsageColumn)
    {
      os << "  " << usage << "\n";
      first = false;
    }
    while (std::getline(summary, line))
    {
      os << "  " << std::left << std::setw(UsageColumn) << (first ? usage : std::string()) << line
         << "\n";
      first = false;
    }
  }
}

int DispatchCommand(const std::string& prefix, const std::vector<Command>& table,
  const std::vector<std::string>& args)
{
  const Command* fallback = nullptr;
  for (const Command& command : table)
  {
    if (command.Name.empty())
    {
      fallback = &command;
    }
    else if (!args.empty() && args[0] == command.Name)
    {
      const std::vector<std::string> rest(args.begin() + 1, args.end());
      return command.Run ? command.Run(rest)
                         : DispatchCommand(prefix + " " + command.Name, command.Subcommands, rest);
    }
  }
  // The unnamed command takes options only: a word first is a subcommand's name mistyped, not
  // a reason to run the default (`bench foo` ran the two-minute relief benchmark).
  if (fallback && (args.empty() || args[0].rfind('-', 0) == 0))
  {
    return fallback->Run(args);
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    PrintGroupHelp(std::cout, prefix, table);
    return args.empty() ? 2 : 0;
  }
  std::cerr << prefix << ": unknown "
            << (prefix.find(' ') == std::string::npos ? "command" : "subcommand") << " '" << args[0]
            << "'\n";
  PrintGroupHelp(std::cerr, prefix, table);
  return 2;
}

} // namespace mesolight
