// Numbers written as text, as every face writes them: "x,y,z" vectors and 16-number matrices. One
// parser, so that the command line, a point API's option text and a texgen plane ("MODE:a,b,c,d")
// accept the same spellings and refuse the others with the same message.
#pragma once

#include <string>
#include <utility>

#include "core/math.h"

namespace uvtk {

// `n` comma-separated finite numbers; throws UsageError naming `option` ("--eye: expected 3
// comma-separated finite numbers, found '1,2'").
Eigen::VectorXd parseNumbers(const std::string& text, int n, const std::string& option);

// A 4x4 matrix from 16 numbers separated by spaces or commas, column-major like glLoadMatrix.
Mat4 parseMatrix(const std::string& text, const std::string& option);

// A picture's size "WxH", or "N" meaning NxN, with 1 <= W, H <= 16384 pixels; throws UsageError
// naming `option`.
std::pair<int, int> parseImageSize(const std::string& text, const std::string& option);

// A texture's size "W,H", or "N" meaning N,N, with 1 <= W, H <= 16384 texels; throws UsageError
// naming `option`.
std::pair<int, int> parseTextureSize(const std::string& text, const std::string& option);

}  // namespace uvtk
