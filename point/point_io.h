// Points in and out as `uvtk eval` reads and writes them: rows of CSV or JSON lines (with optional
// normals and eyes), each evaluated by a PointEvaluator and written with its (u, v, w, q), status
// and reason, every number in 17 significant digits (docs/eval.md). A static library of its own:
// the installed point API (libuvtk_point.so) does not carry it.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "param/parameters.h"
#include "uvtk/point.h"

namespace uvtk::point {

enum class TextFormat { Csv, Json };

// One point to evaluate: from --point (line 0) or from line `line` of the rows.
struct PointRow {
  std::size_t line = 0;
  Vector3 position{};
  std::optional<Vector3> normal, eye;
};

// "x,y,z" of --point or --normal, as `option` (non-finite values allowed: they make the point
// invalid); throws UsageError naming `option` otherwise.
Vector3 parseTriple(const std::string& text, const char* option);

// The rows of `in`: CSV (x,y,z[,nx,ny,nz][,ex,ey,ez], or the columns an optional header names) or
// JSON lines ({"p": [...], "n": [...], "eye": [...]}); blank lines and # comments skipped. Throws
// InputError "<stdin>:LINE: error: expected ..., found ..." for a malformed row.
std::vector<PointRow> readPointRows(std::istream& in, TextFormat format);

struct EvalJob {
  std::vector<PointRow> rows;  // the points given as options
  std::istream* in = nullptr;  // or, when set, the rows to read from it (in `input` format)
  TextFormat input = TextFormat::Csv, format = TextFormat::Csv;
  std::optional<Vector3> defaultNormal;  // of the points without their own
  std::string mesh;    // what a fitted placement and --seam-place auto are fitted to; none when empty
  std::string output;  // written atomically; stdout when empty
};

// The job of `uvtk eval`'s --point and --normal values (`normals`: one for every point, or one per
// point): those points, or without any the rows on stdin, with at most one normal (the rows'
// without their own). Throws UsageError for other counts of normals, for --input with --point
// (`inputGiven`) and for rows to read from a terminal.
EvalJob evalJobOf(const std::vector<std::string>& points, const std::vector<std::string>& normals, bool inputGiven);

// The end of `uvtk eval --help`: the points in, the placement, the lines out, the statuses.
extern const char* const kEvalHelp;

// Points by status: [int(Status)].
struct EvalCounts {
  std::size_t points = 0;
  std::size_t byStatus[4] = {};
};

// Resolves `mapping`, the parameters of inspect::readMapping (a reflection without an eye takes
// each row's when the rows are read), reads
// the mesh and the rows, checks every row, then evaluates and writes each point as it goes.
// Throws UsageError for a mapping the points cannot take, InputError for a malformed row or
// mesh, OutputError when the output cannot be written.
EvalCounts evaluatePoints(const EvalJob& job, const param::ParameterDictionary& mapping);

}  // namespace uvtk::point
