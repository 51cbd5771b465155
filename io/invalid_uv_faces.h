// The faces a uvtk writer lists as having corners without a valid UV. Every format stores some UV
// at such a corner ((0, 0): OBJ `vt 0 0`, PLY `s t = 0 0`, glTF (0, 1) as v is flipped), so the
// writers list the faces where each format keeps notes (an OBJ or PLY comment, the glTF mesh's
// extras.uvtk.invalid_faces), and the readers give those corners back without a UV: a file that
// `uvtk map` wrote is judged as the map was, not by the (0, 0) its invalid corners hold.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

// The texts of the lists. The first line of a list says how many faces it holds; the numbers go on
// at most a few thousand to a line, on lines of their own ("more"), so that no line is long.
// OBJ: "# N faces have corners without a valid UV (written as vt 0 0); 1-based face numbers: 2 7"
//      "# more 1-based face numbers: 9 12"
inline constexpr std::string_view kObjInvalidFacesFirst =
    " faces have corners without a valid UV (written as vt 0 0); 1-based face numbers:";
inline constexpr std::string_view kObjInvalidFacesMore = "# more 1-based face numbers:";
// PLY: "comment uvtk: N faces have corners without a valid UV (written as s t = 0 0); 0-based face numbers: 1 6"
//      "comment uvtk: more 0-based face numbers: 8 11"
inline constexpr std::string_view kPlyInvalidFacesFirst =
    " faces have corners without a valid UV (written as s t = 0 0); 0-based face numbers:";
inline constexpr std::string_view kPlyInvalidFacesMore = "comment uvtk: more 0-based face numbers:";
inline constexpr std::size_t kInvalidFacesPerLine = 10000;

// The faces a writer lists: those with a corner without a valid UV (kFaceInvalid), ascending.
std::vector<std::size_t> invalidUvFaces(const UvMap& uvs);

// The face numbers of one line of a list, 0-based (`firstNumber` 1: the line's are 1-based),
// appended to `faces`. `line` is a whole OBJ comment ("# ...") or PLY header line ("comment ...");
// `first` and `more` are one format's texts above; the first line is `# N` or `comment uvtk: N`
// then `first`, where `lead` is "# " or "comment uvtk: ". False, with `faces` unchanged, when the
// line is not a line of a list (any other comment).
bool readInvalidFaceLine(std::string_view line, std::string_view lead, std::string_view first, std::string_view more,
                         std::size_t firstNumber, std::vector<std::size_t>& faces);

// Marks the corners of the listed faces (0-based among the `faceCount` faces from `firstFace`)
// that hold exactly (u, v) = (0, 0) as without a UV (corner index -1); numbers beyond the faces,
// and faces without a (0, 0) corner, are left alone (the list is a note, not the data). A valid
// corner that is exactly (0, 0) in a listed face is marked too: the face was invalid either way.
// Appends to `marked` each face (its index in the mesh) in which a corner was marked, once.
void markListedInvalidFaces(Mesh& mesh, std::size_t firstFace, std::size_t faceCount,
                            const std::vector<std::size_t>& faces, std::vector<std::size_t>& marked);

}  // namespace uvtk::io
