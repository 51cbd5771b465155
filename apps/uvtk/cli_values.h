// Parsing of option values shared by the subcommands: vectors written as "x,y,z".
#pragma once

#include <string>

#include "core/math.h"

namespace uvtk::cli {

// Parses `text` as `n` comma-separated finite numbers; throws UsageError naming `option`.
Eigen::VectorXd parseNumbers(const std::string& text, int n, const std::string& option);

inline Vec2 parseVec2(const std::string& text, const std::string& option) { return parseNumbers(text, 2, option); }
inline Vec3 parseVec3(const std::string& text, const std::string& option) { return parseNumbers(text, 3, option); }
inline Vec4 parseVec4(const std::string& text, const std::string& option) { return parseNumbers(text, 4, option); }

// A 4x4 matrix from 16 numbers separated by spaces or commas, column-major like glLoadMatrix.
Mat4 parseMatrix(const std::string& text, const std::string& option);

}  // namespace uvtk::cli
