// SPDX-License-Identifier: BSD-3-Clause
#include "ProgressLine.h"

#include <unistd.h>

#include <iostream>
#include <memory>

namespace mesolight
{

namespace
{
// The progress line open on stderr (none when empty): what it is about.
std::string& OpenLine()
{
  static std::string what;
  return what;
}

bool StderrIsTerminal()
{
  static const bool terminal = isatty(STDERR_FILENO) != 0;
  return terminal;
}
} // namespace

void EndProgressLine()
{
  if (!OpenLine().empty())
  {
    std::cerr << (StderrIsTerminal() ? "\r\033[K" : "\n") << std::flush;
    OpenLine().clear();
  }
}

ProgressCallback PrintedProgress(const std::string& what)
{
  auto last = std::make_shared<int>(-1);
  return [what, last](double fraction)
  {
    const int step = static_cast<int>(fraction * 10.0);
    if (step == *last)
    {
      return true;
    }
    *last = step;
    if (StderrIsTerminal())
    {
      std::cerr << "\r" << what << " " << step * 10 << "%";
    }
    else
    {
      if (OpenLine() != what)
      {
        EndProgressLine();
        std::cerr << what;
      }
      std::cerr << " " << step * 10 << "%";
    }
    OpenLine() = what;
    if (step >= 10)
    {
      std::cerr << "\n";
      OpenLine().clear();
    }
    std::cerr << std::flush;
    return true;
  };
}

} // namespace mesolight
