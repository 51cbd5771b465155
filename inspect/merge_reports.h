// The JSON reports of many independent runs (GNU parallel tasks, cluster job arrays, `uvtk map`
// batches, scene runs) merged into one file with totals: `uvtk merge-reports` (docs/scale-out.md).
#pragma once

#include <string>
#include <vector>

namespace uvtk::inspect {

// Merges the report files `inputs` names (a file, or every *.json below a folder, sorted) into
// `output`: {"tool", "reports": [{"path", "report"}], "totals"}, each report's keys in their order.
// A file is merged once however often it is named, and never `output` itself (a merged file
// written into a folder it merges). Throws InputError for a missing file, an empty folder or
// invalid JSON ("FILE:LINE:COLUMN: error: invalid JSON: ...").
//
// Counting: totals.reports is the number of report files merged. totals.failed counts failed
// runs: a report whose "status" is "failed" or whose "failures" is a non-empty array or object
// counts one; a `uvtk map DIR --json` batch.json (a report with a "meshes" array) counts each of
// its failed meshes, which have no summary file of their own (its meshes that succeeded are
// counted by their summaries, so merging that folder whole counts every mesh once).
// totals.verdicts counts the reports whose top-level "verdict" is "pass", "warn" or "fail" (map
// summaries, reports; a batch's meshes are counted by their own summaries).
// totals.milliseconds sums, per stage, the numbers of every report's top-level "milliseconds" but
// "total" and "wall", a run's whole time: runs in parallel overlap, so those go to
// totals.run_milliseconds, their "sum" (work) and the "longest" with its "longest_report" (a lower
// bound of the time all took). Returns the line `uvtk merge-reports` prints: "N reports merged (a
// pass, b warn, c fail), k failed".
std::string mergeReports(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace uvtk::inspect
