// SPDX-License-Identifier: BSD-3-Clause
// CleanVTKMessage: the user-facing text of a VTK error or warning, the one implementation for
// every place that shows VTK's messages as its own (the mesolight tool's console, the evaluation
// scenes' error strings). Plain C++ (no VTK types: it works on the text vtkErrorMacro builds).
#ifndef mesolight_VTKMessage_h
#define mesolight_VTKMessage_h

#include <cctype>
#include <string>

namespace mesolight
{

// vtkErrorMacro and vtkWarningMacro write "ERROR: In FILE, line N\nvtkClass (0xADDRESS): text\n\n"
// (and "Warning: In", "Generic Warning: In"); what the user needs is "text". Drops the location
// line, then the object's "NAME (ADDRESS): " prefix, then trailing newlines and spaces. Text in
// another form is only trimmed.
inline std::string CleanVTKMessage(std::string text)
{
  const std::size_t lineEnd = text.find('\n');
  if (lineEnd != std::string::npos)
  {
    const std::size_t in = text.find(": In ");
    if (in != std::string::npos && in < lineEnd && text.find(", line ", in) < lineEnd)
    {
      text.erase(0, lineEnd + 1);
    }
  }
  // "NAME (ADDRESS): ": NAME without spaces, ADDRESS of hexadecimal digits and an optional 0x.
  const std::size_t open = text.find(" (");
  const std::size_t close = text.find("): ");
  if (open != std::string::npos && close != std::string::npos && open > 0 && open + 2 < close &&
    text.find_first_of(" \n") == open)
  {
    bool address = true;
    for (std::size_t i = open + 2; i < close; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      address = address && (std::isxdigit(c) || c == 'x' || c == 'X');
    }
    if (address)
    {
      text.erase(0, close + 3);
    }
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

} // namespace mesolight

#endif
