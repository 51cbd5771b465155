// The faces a uvtk writer lists in a file, so that a file `uvtk map` wrote is judged as the map
// was: faces with corners without a valid UV (every format stores some UV there: OBJ `vt 0 0`, PLY
// `s t = 0 0`, glTF (0, 1) as v is flipped), pole faces (their corners on the projector's axis,
// fanned) and faces turned away from a planar projection (mirrored by design, not flipped). Each
// format keeps the lists where it keeps notes (an OBJ or PLY comment, the glTF mesh's
// extras.uvtk), and the readers give them back: invalid corners without a UV, the other lists as
// Mesh::listedFaceFlags.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

// One list in each format's words. The first line of a list says how many faces it holds; the
// numbers go on at most kFacesPerLine to a line, on lines of their own ("more"), so that no line is
// long. OBJ: "# N" then objFirst, then 1-based numbers; "objMore 9 12". PLY: "comment uvtk: N" then
// plyFirst, 0-based; "plyMore 8 11". glTF: extras.uvtk[gltfKey], 0-based.
struct FaceList {
  FaceFlag flag;
  std::string_view objFirst, objMore, plyFirst, plyMore, gltfKey;
};
inline constexpr std::array<FaceList, 3> kFaceLists = {{
    {kFaceInvalid, " faces have corners without a valid UV (written as vt 0 0); 1-based face numbers:",
     "# more 1-based face numbers:",
     " faces have corners without a valid UV (written as s t = 0 0); 0-based face numbers:",
     "comment uvtk: more 0-based face numbers:", "invalid_faces"},
    {kFacePole, " faces are pole faces (their corners on the projector's axis fanned); 1-based face numbers:",
     "# more 1-based pole face numbers:",
     " faces are pole faces (their corners on the projector's axis fanned); 0-based face numbers:",
     "comment uvtk: more 0-based pole face numbers:", "pole_faces"},
    {kFaceTurnedAway,
     " faces are turned away from the projection (mirrored by design); 1-based face numbers:",
     "# more 1-based turned-away face numbers:",
     " faces are turned away from the projection (mirrored by design); 0-based face numbers:",
     "comment uvtk: more 0-based turned-away face numbers:", "turned_away_faces"},
}};
inline constexpr std::size_t kFacesPerLine = 10000;

// The faces of one list as a reader gathers them, 0-based, per entry of kFaceLists.
using ListedFaces = std::array<std::vector<std::size_t>, kFaceLists.size()>;

// The faces with `flag`, ascending; none without UVs (null).
std::vector<std::size_t> facesWith(const UvMap* uvs, FaceFlag flag);

// The face numbers of one line of a list appended to its entry of `lists`: `line` is a whole OBJ
// comment ("# ...", `ply` false: 1-based numbers) or PLY header line ("comment ...", `ply` true:
// 0-based). False, with `lists` unchanged, when the line is not a line of a list (any other comment).
bool readFaceListLine(std::string_view line, bool ply, ListedFaces& lists);

// Applies the lists to the `faceCount` faces from `firstFace` (numbers 0-based among them; beyond
// them, ignored: a list is a note, not the data). Invalid faces: their corners that hold exactly
// (u, v) = (0, 0) become corners without a UV (corner index -1; a valid corner at (0, 0) in a
// listed face too: the face was invalid either way), and each face in which a corner was marked is
// appended to `markedInvalid` once. Pole and turned-away faces: their bits in
// mesh.listedFaceFlags (sized to the mesh's faces when a bit is set).
void applyFaceLists(Mesh& mesh, std::size_t firstFace, std::size_t faceCount, const ListedFaces& lists,
                    std::vector<std::size_t>& markedInvalid);

}  // namespace uvtk::io
