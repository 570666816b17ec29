// A small, strict command-line parser for the `mesolight` tool: every option is declared with
// its help text, so `--help` documents exactly what is accepted and unknown options are errors.
#ifndef mesolight_CommandLine_h
#define mesolight_CommandLine_h

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace mesolight
{

class CommandLine
{
public:
  /** Declares an option taking a value (e.g. "--out", "FILE", "where to write"). */
  void AddValue(const std::string& name, const std::string& meta, const std::string& help,
    const std::string& defaultValue = "");
  /** Declares a flag without a value. */
  void AddFlag(const std::string& name, const std::string& help);

  /** Parses args; positional arguments are kept in order. False with a message on error. */
  bool Parse(const std::vector<std::string>& args, std::string& error);

  bool Has(const std::string& name) const;
  std::string Get(const std::string& name) const;
  /** Numeric accessors; false with a message when the value is not a finite number in range. */
  bool GetInt(const std::string& name, int low, int high, int& value, std::string& error) const;
  bool GetDouble(
    const std::string& name, double low, double high, double& value, std::string& error) const;
  const std::vector<std::string>& Positional() const { return this->PositionalArgs; }

  void PrintOptions(std::ostream& os) const;

private:
  struct Option
  {
    std::string Meta;
    std::string Help;
    std::string Default;
    bool TakesValue = false;
  };
  std::vector<std::string> Order;
  std::map<std::string, Option> Options;
  std::map<std::string, std::string> Values;
  std::vector<std::string> PositionalArgs;
};

} // namespace mesolight

#endif
