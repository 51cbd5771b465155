#include "io/invalid_uv_faces.h"

#include <charconv>

namespace uvtk::io {

namespace {

bool startsWith(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

std::string_view skipBlanks(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  return text;
}

// The whole numbers of `text`, separated by blanks; false at anything else.
bool readNumbers(std::string_view text, std::size_t firstNumber, std::vector<std::size_t>& faces) {
  for (text = skipBlanks(text); !text.empty(); text = skipBlanks(text)) {
    std::size_t number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error != std::errc() || number < firstNumber) return false;
    text.remove_prefix(static_cast<std::size_t>(end - text.data()));
    if (!text.empty() && text.front() != ' ' && text.front() != '\t') return false;
    faces.push_back(number - firstNumber);
  }
  return true;
}

}  // namespace

std::vector<std::size_t> invalidUvFaces(const UvMap& uvs) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < uvs.faceCount(); ++f)
    if (uvs.faceHas(f, kFaceInvalid)) faces.push_back(f);
  return faces;
}

bool readInvalidFaceLine(std::string_view line, std::string_view lead, std::string_view first, std::string_view more,
                         std::size_t firstNumber, std::vector<std::size_t>& faces) {
  std::string_view numbers;
  if (startsWith(line, more)) {
    numbers = line.substr(more.size());
  } else if (startsWith(line, lead)) {
    std::string_view rest = line.substr(lead.size());
    std::size_t digits = 0;
    while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
    rest.remove_prefix(digits);
    if (digits == 0 || !startsWith(rest, first)) return false;
    numbers = rest.substr(first.size());
  } else {
    return false;
  }
  const std::size_t before = faces.size();
  if (readNumbers(numbers, firstNumber, faces)) return true;
  faces.resize(before);
  return false;
}

void markListedInvalidFaces(Mesh& mesh, std::size_t firstFace, std::size_t faceCount,
                            const std::vector<std::size_t>& faces, std::vector<std::size_t>& marked) {
  for (const std::size_t listed : faces) {
    // A corner table may end before the faces do (a glTF primitive without UVs after those with them).
    if (listed >= faceCount || firstFace + listed >= mesh.cornerTexcoords.size()) continue;
    Triangle& corners = mesh.cornerTexcoords[firstFace + listed];
    bool any = false;
    for (int& t : corners)
      if (t >= 0 && mesh.texcoords[static_cast<std::size_t>(t)].x() == 0.0 &&
          mesh.texcoords[static_cast<std::size_t>(t)].y() == 0.0) {
        t = -1;
        any = true;
      }
    if (any) marked.push_back(firstFace + listed);
  }
}

}  // namespace uvtk::io
