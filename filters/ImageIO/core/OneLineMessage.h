// SPDX-License-Identifier: BSD-3-Clause
// Library messages (OpenImageIO's in particular) may span several lines; VTK error messages
// read best as one.
#ifndef mesolight_OneLineMessage_h
#define mesolight_OneLineMessage_h

#include <cctype>
#include <string>

namespace mesolight
{

/** The text on one line ("; " between its lines), trimmed; "no details" when empty. */
inline std::string OneLineMessage(const std::string& text)
{
  std::string s;
  for (char c : text)
  {
    if (c != '\n' && c != '\r')
    {
      s += c;
    }
    else if (!s.empty() && s.back() != ' ')
    {
      s += "; ";
    }
  }
  while (!s.empty() && (std::isspace(static_cast<unsigned char>(s.back())) || s.back() == ';'))
  {
    s.pop_back();
  }
  return s.empty() ? std::string("no details") : s;
}

} // namespace mesolight

#endif
