// SPDX-License-Identifier: BSD-3-Clause
#include "CommandLine.h"

#include "OutputFile.h" // CheckOutputOptions

#include <cctype>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <strings.h>

namespace mesolight
{
namespace
{
// A finite number in [low, high]; the message says which option and item is wrong.
bool ParseNumber(const std::string& name, const std::string& text, double low, double high,
  double& value, std::string& error)
{
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(parsed))
  {
    error = "option " + name + ": '" + text + "' is not a number";
    return false;
  }
  if (parsed < low || parsed > high)
  {
    std::ostringstream range;
    range << std::setprecision(12) // bounds such as 1 << 26 in full, not 6.71089e+07
          << "option " << name << ": " << parsed << " is outside [" << low << ", " << high << "]";
    error = range.str();
    return false;
  }
  value = parsed;
  return true;
}

std::vector<std::string> SplitCommas(const std::string& text)
{
  std::vector<std::string> items;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    while (!item.empty() && item.front() == ' ')
    {
      item.erase(item.begin());
    }
    while (!item.empty() && item.back() == ' ')
    {
      item.pop_back();
    }
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}
} // namespace

CommandLine::CommandLine(const std::string& name, const std::string& synopsis)
  : Name(name)
  , Synopsis(synopsis)
{
}

void CommandLine::AddValue(const std::string& name, const std::string& meta,
  const std::string& help, const std::string& defaultValue)
{
  this->Order.push_back(name);
  Option& option = this->Options[name];
  option.Meta = meta;
  option.Help = help;
  option.Default = defaultValue;
  option.TakesValue = true;
}

void CommandLine::AddFlag(const std::string& name, const std::string& help)
{
  this->Order.push_back(name);
  Option& option = this->Options[name];
  option.Help = help;
  option.TakesValue = false;
}

bool CommandLine::Parse(const std::vector<std::string>& args, std::string& error)
{
  for (size_t i = 0; i < args.size(); ++i)
  {
    const std::string& arg = args[i];
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0)
    {
      if (!arg.empty() && arg[0] == '-' && arg.size() > 1)
      {
        error = "unknown option '" + arg + "' (options are spelled --name)";
        return false;
      }
      this->PositionalArgs.push_back(arg);
      continue;
    }
    std::string name = arg;
    std::string value;
    bool inlineValue = false;
    const size_t eq = arg.find('=');
    if (eq != std::string::npos)
    {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      inlineValue = true;
    }
    auto it = this->Options.find(name);
    if (it == this->Options.end())
    {
      error = "unknown option '" + name + "' (" +
        (this->UnknownOptionHint.empty() ? "see --help" : this->UnknownOptionHint) + ")";
      return false;
    }
    if (it->second.TakesValue)
    {
      if (!inlineValue)
      {
        if (i + 1 >= args.size())
        {
          error = "option " + name + " needs a value (" + it->second.Meta + ")";
          return false;
        }
        value = args[++i];
      }
      if (value.empty())
      {
        // An empty value ("--count ''") would otherwise silently mean the default.
        error = "option " + name + " needs a value (" + it->second.Meta + "), not an empty one";
        return false;
      }
      this->Values[name] = value;
      this->AllValues[name].push_back(value);
    }
    else
    {
      if (inlineValue)
      {
        error = "option " + name + " takes no value";
        return false;
      }
      this->Values[name] = "1";
    }
  }
  for (const auto& [option, anyOf] : this->OptionsNeedingOthers)
  {
    if (this->Has(option) &&
      std::none_of(
        anyOf.begin(), anyOf.end(), [this](const std::string& other) { return this->Has(other); }))
    {
      error = option + " needs ";
      for (size_t k = 0; k < anyOf.size(); ++k)
      {
        error += (k == 0 ? "" : " or ") + anyOf[k];
      }
      return false;
    }
  }
  return true;
}

void CommandLine::AppliesOnlyWith(const std::string& option, const std::vector<std::string>& anyOf)
{
  this->OptionsNeedingOthers.emplace_back(option, anyOf);
}

namespace
{
// The options of the command being run, as VTK property names ("--memory-budget" ->
// "MemoryBudget"), for NameOwnOptions.
std::vector<std::pair<std::string, std::string>>& PropertyOptions()
{
  static std::vector<std::pair<std::string, std::string>> options;
  return options;
}

std::string PropertyName(const std::string& option)
{
  std::string name;
  bool upper = true;
  for (std::size_t i = option.find_first_not_of('-'); i < option.size(); ++i)
  {
    if (option[i] == '-')
    {
      upper = true;
      continue;
    }
    name.push_back(
      upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(option[i]))) : option[i]);
    upper = false;
  }
  return name;
}
} // namespace

std::string NameOwnOptions(const std::string& message)
{
  std::string text = message;
  for (const auto& entry : PropertyOptions())
  {
    const std::string from = "set " + entry.first;
    std::size_t at = text.find(from);
    while (at != std::string::npos)
    {
      const std::size_t end = at + from.size();
      if (end < text.size() && std::isalnum(static_cast<unsigned char>(text[end])))
      {
        at = text.find(from, end); // a longer property name: not this option
        continue;
      }
      text.replace(at + 4, entry.first.size(), entry.second);
      at = text.find(from, at + 4 + entry.second.size());
    }
  }
  return text;
}

bool CommandLine::ParseArguments(const std::vector<std::string>& args, int& status)
{
  PropertyOptions().clear();
  for (const std::string& option : this->Order)
  {
    PropertyOptions().emplace_back(PropertyName(option), option);
  }
  if (this->Options.count("--help") == 0)
  {
    this->AddFlag("--help", "show this help");
  }
  std::string error;
  if (!this->Parse(args, error))
  {
    status = this->UsageError(error);
    return false;
  }
  if (this->Has("--help"))
  {
    this->PrintHelp(std::cout);
    status = 0;
    return false;
  }
  status = 0;
  return true;
}

bool CommandLine::ParseArguments(const std::vector<std::string>& args,
  const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, int& status)
{
  if (!this->ParseArguments(args, status))
  {
    return false;
  }
  std::vector<std::string> inputFiles;
  for (const std::string& input : inputs)
  {
    inputFiles.push_back(this->Get(input));
  }
  if (const std::string problem = CheckOutputOptions(*this, outputs, inputFiles); !problem.empty())
  {
    status = this->UsageError(problem);
    return false;
  }
  return true;
}

int CommandLine::UsageError(const std::string& message) const
{
  std::cerr << this->Name << ": " << message << "\n";
  return 2;
}

void CommandLine::PrintHelp(std::ostream& os) const
{
  os << this->Synopsis << "\nOptions:\n";
  this->PrintOptions(os);
}

bool CommandLine::Has(const std::string& name) const
{
  return this->Values.count(name) > 0;
}

std::vector<std::string> CommandLine::GetAll(const std::string& name) const
{
  const auto it = this->AllValues.find(name);
  return it != this->AllValues.end() ? it->second : std::vector<std::string>();
}

std::string CommandLine::Get(const std::string& name) const
{
  auto it = this->Values.find(name);
  if (it != this->Values.end())
  {
    return it->second;
  }
  auto opt = this->Options.find(name);
  return opt != this->Options.end() ? opt->second.Default : std::string();
}

bool CommandLine::GetDouble(
  const std::string& name, double low, double high, double& value, std::string& error) const
{
  const std::string text = this->Get(name);
  if (text.empty())
  {
    return true; // keep the caller's default
  }
  return ParseNumber(name, text, low, high, value, error);
}

bool CommandLine::CheckVerticalExaggeration(const CommandLine& cl, std::string& error)
{
  if (!cl.Has("--normalize"))
  {
    error = "--vertical-exaggeration needs --normalize (elevations in metres)";
    return false;
  }
  if (cl.Has("--depth-scale"))
  {
    error = "--vertical-exaggeration and --depth-scale: give one";
    return false;
  }
  return true;
}

bool CommandLine::GetNoData(const std::string& name, NoDataOption& option, std::string& error) const
{
  option = NoDataOption();
  if (!this->Has(name))
  {
    return true;
  }
  const std::string text = this->Get(name);
  if (strcasecmp(text.c_str(), "none") == 0)
  {
    option.UseFileValue = false;
    return true;
  }
  option.Use = true;
  if (strcasecmp(text.c_str(), "nan") == 0)
  {
    option.Value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  return this->GetDouble(name, -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), option.Value, error);
}

bool CommandLine::GetInt(
  const std::string& name, int low, int high, int& value, std::string& error) const
{
  double parsed = value;
  if (!this->GetDouble(name, low, high, parsed, error))
  {
    return false;
  }
  if (parsed != std::floor(parsed))
  {
    error = "option " + name + " needs a whole number";
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

bool CommandLine::GetInts(const std::vector<IntOption>& options, std::string& error) const
{
  for (const IntOption& option : options)
  {
    if (!this->GetInt(option.Name, option.Low, option.High, *option.Value, error))
    {
      return false;
    }
  }
  return true;
}

bool CommandLine::GetDoubleList(const std::string& name, double low, double high,
  std::vector<double>& values, std::string& error) const
{
  values.clear();
  for (const std::string& item : SplitCommas(this->Get(name)))
  {
    double value = 0.0;
    if (!ParseNumber(name, item, low, high, value, error))
    {
      return false;
    }
    values.push_back(value);
  }
  if (values.empty())
  {
    error = "option " + name + " needs at least one value";
    return false;
  }
  return true;
}

bool CommandLine::GetIntList(
  const std::string& name, int low, int high, std::vector<int>& values, std::string& error) const
{
  std::vector<double> parsed;
  if (!this->GetDoubleList(name, low, high, parsed, error))
  {
    return false;
  }
  values.clear();
  for (double value : parsed)
  {
    if (value != std::floor(value))
    {
      std::ostringstream message;
      message << "option " << name << ": " << value << " is not a whole number";
      error = message.str();
      return false;
    }
    values.push_back(static_cast<int>(value));
  }
  return true;
}

bool CommandLine::GetSize(
  const std::string& name, int low, int high, int& width, int& height, std::string& error) const
{
  const std::string text = this->Get(name);
  const size_t x = text.find('x');
  char* end1 = nullptr;
  char* end2 = nullptr;
  const long w = x == std::string::npos ? 0 : std::strtol(text.c_str(), &end1, 10);
  const long h = x == std::string::npos ? 0 : std::strtol(text.c_str() + x + 1, &end2, 10);
  if (x == std::string::npos || x == 0 || end1 != text.c_str() + x ||
    end2 == text.c_str() + x + 1 || *end2 != '\0' || w < low || h < low || w > high || h > high)
  {
    error = "option " + name + ": '" + text + "' is not WxH with " + std::to_string(low) +
      " <= W, H <= " + std::to_string(high);
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

bool CommandLine::GetDoubleVector(const std::string& name, size_t count, double* values) const
{
  std::vector<double> list;
  std::string error;
  if (!this->GetDoubleList(name, std::numeric_limits<double>::lowest(),
        std::numeric_limits<double>::max(), list, error) ||
    list.size() != count)
  {
    return false;
  }
  std::copy(list.begin(), list.end(), values);
  return true;
}

std::vector<std::string> CommandLine::GetStringList(const std::string& name) const
{
  return SplitCommas(this->Get(name));
}

void CommandLine::PrintOptions(std::ostream& os) const
{
  // Descriptions start in column 31 and wrap at 100 columns, continuation lines indented to
  // the same column (a terminal's own wrap, or a newline in the text, restarted them at 0).
  constexpr std::size_t column = 31;
  constexpr std::size_t width = 100;
  for (const std::string& name : this->Order)
  {
    const Option& option = this->Options.at(name);
    std::string head = "  " + name + (option.TakesValue ? " " + option.Meta : "");
    std::string text = option.Help;
    if (!option.Default.empty())
    {
      text += " (default: " + option.Default + ")";
    }
    os << std::left << std::setw(column - 1) << head << " ";
    std::size_t at = std::max(column, head.size() + 1);
    std::istringstream words(text);
    std::string word;
    bool first = true;
    while (words >> word)
    {
      if (!first && at + 1 + word.size() > width)
      {
        os << "\n" << std::string(column, ' ');
        at = column;
        first = true;
      }
      os << (first ? "" : " ") << word;
      at += (first ? 0 : 1) + word.size();
      first = false;
    }
    os << "\n";
  }
}

} // namespace mesolight
