// SPDX-License-Identifier: BSD-3-Clause
// The report of `mesolight bench relief` (ReliefSweep.h): the table, the CSV, one chart per view
// angle, relaxed cones vs relief at equal error, and the summary. The run measures; this writes.
#ifndef mesolight_ReliefSweepReport_h
#define mesolight_ReliefSweepReport_h

#include "ReliefSweep.h"

#include <ostream>
#include <string>
#include <vector>

namespace mesolight
{
namespace report
{

/** value with a fixed number of decimals. */
std::string Fixed(double value, int precision);

/** The table's header and one row per configuration. */
void PrintHeader(std::ostream& out);
void PrintRow(std::ostream& out, const ReliefSweepRow& r);

/** One CSV row per configuration; false when the file cannot be written. */
bool WriteCsv(const std::string& file, const std::vector<ReliefSweepRow>& rows,
  const ReliefSweepSettings& settings);

/**
 * One chart per view angle into settings.PlotDirectory: every configuration's ms/frame and mean
 * hit error, averaged over the maps, one series per method, and the Pareto front.
 */
bool WritePlots(const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows,
  const std::vector<std::string>& mapLabels, std::ostream& out);

/** Best settings per method and angle, and relaxed cones vs relief at equal hit error. */
void PrintSummary(
  const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows, std::ostream& out);

} // namespace report
} // namespace mesolight

#endif
