#include "io/face_lists.h"

#include <charconv>
#include <optional>

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

// The numbers after `first` on a list's first line ("LEAD N first ...") or after `more`; none when
// the line is neither.
std::optional<std::string_view> listNumbers(std::string_view line, std::string_view lead, std::string_view first,
                                            std::string_view more) {
  if (startsWith(line, more)) return line.substr(more.size());
  if (!startsWith(line, lead)) return std::nullopt;
  std::string_view rest = line.substr(lead.size());
  std::size_t digits = 0;
  while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
  rest.remove_prefix(digits);
  if (digits == 0 || !startsWith(rest, first)) return std::nullopt;
  return rest.substr(first.size());
}

}  // namespace

std::vector<std::size_t> facesWith(const UvMap* uvs, FaceFlag flag) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; uvs && f < uvs->faceCount(); ++f)
    if (uvs->faceHas(f, flag)) faces.push_back(f);
  return faces;
}

bool readFaceListLine(std::string_view line, bool ply, ListedFaces& lists) {
  for (std::size_t i = 0; i < kFaceLists.size(); ++i) {
    const FaceList& list = kFaceLists[i];
    const std::optional<std::string_view> numbers =
        ply ? listNumbers(line, "comment uvtk: ", list.plyFirst, list.plyMore)
            : listNumbers(line, "# ", list.objFirst, list.objMore);
    if (!numbers) continue;
    std::vector<std::size_t>& faces = lists[i];
    const std::size_t before = faces.size();
    if (readNumbers(*numbers, ply ? 0 : 1, faces)) return true;
    faces.resize(before);
    return false;
  }
  return false;
}

void applyFaceLists(Mesh& mesh, std::size_t firstFace, std::size_t faceCount, const ListedFaces& lists,
                    std::vector<std::size_t>& markedInvalid) {
  for (std::size_t i = 0; i < kFaceLists.size(); ++i) {
    const FaceFlag flag = kFaceLists[i].flag;
    for (const std::size_t listed : lists[i]) {
      if (listed >= faceCount) continue;
      const std::size_t face = firstFace + listed;
      if (flag != kFaceInvalid) {
        if (mesh.listedFaceFlags.size() < mesh.triangles.size()) mesh.listedFaceFlags.resize(mesh.triangles.size(), 0);
        mesh.listedFaceFlags[face] |= flag;
        continue;
      }
      // A corner table may end before the faces do (a glTF primitive without UVs after those with them).
      if (face >= mesh.cornerTexcoords.size()) continue;
      bool any = false;
      for (int& t : mesh.cornerTexcoords[face])
        if (t >= 0 && mesh.texcoords[static_cast<std::size_t>(t)].x() == 0.0 &&
            mesh.texcoords[static_cast<std::size_t>(t)].y() == 0.0) {
          t = -1;
          any = true;
        }
      if (any) markedInvalid.push_back(face);
    }
  }
}

}  // namespace uvtk::io
