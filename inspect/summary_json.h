// The projector's record of the mapping as JSON: what it did (poles, invalid vertices, cut faces).
// With `triplanar`, the faces each axis's projection wrote. The seams, counts and verdict are the judgement's (measures_json.h), not recounted here.
#pragma once

#include <nlohmann/json.hpp>

#include "param/projector.h"

namespace uvtk::inspect {

inline nlohmann::json summaryJson(const param::MappingSummary& s, bool triplanar = false) {
  nlohmann::json j = {{"vertices", s.vertices},
          {"faces", s.faces},
          {"straddling_faces", s.straddlingFaces},
          {"pole_vertices", s.poleVertices},
          {"pole_faces", s.poleFaces},
          {"invalid_vertices", s.invalidVertices},
          {"invalid_faces", s.invalidFaces},
          {"cube_seam_faces", s.cubeSeamFaces},
          {"cap_faces", s.capFaces},
          {"added_vertices", s.addedVertices},
          {"added_faces", s.addedFaces},
          {"invalid_vertex_list", s.invalidVertexList},
          {"pole_vertex_list", s.poleVertexList},
          {"pole_face_list", s.poleFaceList}};
  // One UV per corner cannot hold a blend: each face carries its dominant axis's projection.
  if (triplanar)
    j["triplanar_faces"] = {{"x", s.triplanarFaces[0]}, {"y", s.triplanarFaces[1]}, {"z", s.triplanarFaces[2]}};
  return j;
}

}  // namespace uvtk::inspect
