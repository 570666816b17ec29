#include "CommandLine.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace mesolight
{

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
      error = "unknown option '" + name + "' (see --help)";
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
      this->Values[name] = value;
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
  return true;
}

bool CommandLine::Has(const std::string& name) const
{
  return this->Values.count(name) > 0;
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
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(parsed))
  {
    error = "option " + name + ": '" + text + "' is not a number";
    return false;
  }
  if (parsed < low || parsed > high)
  {
    std::ostringstream range;
    range << "option " << name << ": " << parsed << " is outside [" << low << ", " << high << "]";
    error = range.str();
    return false;
  }
  value = parsed;
  return true;
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

void CommandLine::PrintOptions(std::ostream& os) const
{
  for (const std::string& name : this->Order)
  {
    const Option& option = this->Options.at(name);
    std::string head = "  " + name + (option.TakesValue ? " " + option.Meta : "");
    os << std::left << std::setw(30) << head << " " << option.Help;
    if (!option.Default.empty())
    {
      os << " (default: " << option.Default << ")";
    }
    os << "\n";
  }
}

} // namespace mesolight
