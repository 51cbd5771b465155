// The mapping summary as JSON, the same numbers as the one-line summary on stderr.
#pragma once

#include <nlohmann/json.hpp>

#include "param/projector.h"

namespace uvtk::cli {

inline nlohmann::json summaryJson(const param::MappingSummary& s) {
  return {{"vertices", s.vertices},
          {"faces", s.faces},
          {"straddling_faces", s.straddlingFaces},
          {"seam_edges", s.seamEdges},
          {"seam_length", s.seamLength},
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
}

}  // namespace uvtk::cli
