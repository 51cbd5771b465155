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
// totals.milliseconds sums, per key, the numbers of every report's top-level "milliseconds".
void mergeReports(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace uvtk::inspect
