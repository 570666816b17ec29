// SPDX-License-Identifier: BSD-3-Clause
// A small, strict command-line parser for the `mesolight` tool: every option is declared with
// its help text, so `--help` documents exactly what is accepted and unknown options are errors.
// Help and usage errors are written here once: a command gives its name and synopsis, and
// ParseArguments prints the help on --help (exit 0) or the error on bad arguments (exit 2).
#ifndef mesolight_CommandLine_h
#define mesolight_CommandLine_h

#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mesolight
{

class CommandLine
{
public:
  CommandLine() = default;
  /**
   * name: the command as typed ("mesolight bake"), the prefix of its error messages; synopsis:
   * its usage line and description, printed by --help above the options.
   */
  CommandLine(const std::string& name, const std::string& synopsis);

  /** Declares an option taking a value (e.g. "--out", "FILE", "where to write"). */
  void AddValue(const std::string& name, const std::string& meta, const std::string& help,
    const std::string& defaultValue = "");
  /** Declares a flag without a value. */
  void AddFlag(const std::string& name, const std::string& help);
  /** What an unknown option's error suggests instead of "see --help" (e.g. the mode that has
   *  it). */
  void SetUnknownOptionHint(const std::string& hint) { this->UnknownOptionHint = hint; }
  /**
   * Declares that `option` only does something together with one of `anyOf`: given without them
   * it is a usage error ("--height needs --depth-file") when parsed, not accepted and ignored.
   */
  void AppliesOnlyWith(const std::string& option, const std::vector<std::string>& anyOf);

  /** Parses args; positional arguments are kept in order. False with a message on error. */
  bool Parse(const std::vector<std::string>& args, std::string& error);

  /**
   * Declares --help (last, unless declared), parses args and handles what ends the command
   * there: on --help prints the help and sets status 0; on an error prints "NAME: error" and sets
   * status 2. True when the command goes on.
   */
  bool ParseArguments(const std::vector<std::string>& args, int& status);
  /**
   * ParseArguments, then the files the command will write checked before any work
   * (CheckOutputOptions, OutputFile.h): the output options `outputs` may not name the files of
   * the options `inputs` nor each other; a problem is a usage error (status 2).
   */
  bool ParseArguments(const std::vector<std::string>& args, const std::vector<std::string>& outputs,
    const std::vector<std::string>& inputs, int& status);
  /** Prints "NAME: message" on stderr; returns 2, the exit code of a usage error. */
  int UsageError(const std::string& message) const;
  /** Prints the synopsis and the options. */
  void PrintHelp(std::ostream& os) const;

  bool Has(const std::string& name) const;
  std::string Get(const std::string& name) const;
  /** Numeric accessors; false with a message when the value is not a finite number in range. */
  bool GetInt(const std::string& name, int low, int high, int& value, std::string& error) const;
  /** An integer option for GetInts: its name, its range and where its value goes. */
  struct IntOption
  {
    std::string Name;
    int Low;
    int High;
    int* Value;
  };
  /** GetInt of each option in order; false with the first bad one's message. */
  bool GetInts(const std::vector<IntOption>& options, std::string& error) const;
  bool GetDouble(
    const std::string& name, double low, double high, double& value, std::string& error) const;
  /** A no-data value option: a number or "nan" (Use, Value), or "none" (UseFileValue false: not
   *  even the value a GeoTIFF names). Absent: the file's own value applies, if it names one. */
  struct NoDataOption
  {
    bool Use = false;
    double Value = 0.0;
    bool UseFileValue = true;
  };
  bool GetNoData(const std::string& name, NoDataOption& option, std::string& error) const;
  /** The help text of every command's --no-data. */
  static constexpr const char* NoDataHelp =
    "texels holding this value (e.g. -32768 in an int16 DEM; nan) have no data: left out of "
    "--normalize's range and drawn as the lowest ground. Default: the value a GeoTIFF names "
    "(GDAL_NODATA), if any; none: not even that one";
  /** The help text of --relief-normalize (trace, vlf render, vlf view). */
  static constexpr const char* ReliefNormalizeHelp =
    "stretch the relief images' value range to [0, 1], as render's --normalize does: elevation "
    "maps in metres (DEMs, signed integers), whose no-data value a GeoTIFF names is left out";
  /** The help text of every command's --vertical-exaggeration. */
  static constexpr const char* VerticalExaggerationHelp =
    "a georeferenced elevation map (GeoTIFF, SRTM .hgt) at its true vertical scale times E, in "
    "place of --depth-scale: the relief as deep, relative to its width, as the terrain is, times "
    "E (needs --normalize)";
  /** --vertical-exaggeration's companions: --normalize given, --depth-scale not; false with a
   *  message otherwise. */
  static bool CheckVerticalExaggeration(const CommandLine& cl, std::string& error);
  /**
   * Comma-separated lists ("512,1024"). Every item must be a number in [low, high] (whole for
   * GetIntList), and there must be at least one; false with a message naming the option and the
   * item otherwise.
   */
  bool GetIntList(
    const std::string& name, int low, int high, std::vector<int>& values, std::string& error) const;
  bool GetDoubleList(const std::string& name, double low, double high, std::vector<double>& values,
    std::string& error) const;
  /**
   * A WxH value ("800x600") with both sides whole numbers in [low, high]; false with a message
   * naming the option otherwise.
   */
  bool GetSize(
    const std::string& name, int low, int high, int& width, int& height, std::string& error) const;
  /** An X,Y,Z-style value: exactly count finite numbers. False otherwise. */
  bool GetDoubleVector(const std::string& name, size_t count, double* values) const;
  /** The items of a comma-separated list, spaces around them and empty items dropped. */
  std::vector<std::string> GetStringList(const std::string& name) const;
  /** Every value a repeatable option was given, in order (Get gives the last). */
  std::vector<std::string> GetAll(const std::string& name) const;
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
  std::string Name;
  std::string Synopsis;
  std::vector<std::string> Order;
  std::map<std::string, Option> Options;
  std::map<std::string, std::string> Values;
  std::map<std::string, std::vector<std::string>> AllValues;
  std::vector<std::string> PositionalArgs;
  std::string UnknownOptionHint;
  std::vector<std::pair<std::string, std::vector<std::string>>> OptionsNeedingOthers;
};

/**
 * A VTK message as the tool shows it: "set Property" (a filter's advice, e.g. "set MemoryBudget")
 * becomes "set --property" when the command last parsed declares that option, so the message
 * names what the user can type.
 */
std::string NameOwnOptions(const std::string& message);

} // namespace mesolight

#endif
