"""The ecosystem's array layouts (docs/python.md, "Other tools' layouts").

uvtk keeps UVs per corner, (F, 3, 2). Other tools want:

- per-vertex UVs with the vertices split where the corners' UVs differ (xatlas' vmapping, indices,
  uvs; glTF; trimesh; most engines): Mapping.split();
- libigl's (V, F, TC, FTC), texture vertices of their own: Mapping.to_arrays(), Mesh.from_arrays();
- meshio's Mesh: to_meshio() and from_meshio(), per-vertex UVs on the split vertices in
  point_data "s" and "t", the vertex properties uvtk's own PLY files hold (meshio's PLY writer
  skips an (N, 2) array).
"""
try:
    import numpy as _np
except ModuleNotFoundError:  # only while the stubs are made without numpy (uvtk/__init__.py)
    _np = None

from . import _uvtk

__all__ = ["from_meshio", "to_meshio"]


def _corner_keys(values):
    """Per corner, the index of its value among the distinct ones in first-seen order, and those
    values' first corners. Equal means equal numbers (0.0 and -0.0 are one value)."""
    values = _np.ascontiguousarray(values + 0.0)  # -0.0 + 0.0 is 0.0
    rows = values.view(_np.dtype((_np.void, values.dtype.itemsize * values.shape[1]))).ravel()
    _, first, inverse = _np.unique(rows, return_index=True, return_inverse=True)
    order = _np.argsort(first, kind="stable")  # distinct values in the order of their first corner
    rank = _np.empty_like(order)
    rank[order] = _np.arange(order.size)
    return rank[inverse.ravel()], first[order]


def _split(self):
    """(vmapping, indices, uvs), as xatlas gives them and glTF wants them: one vertex per distinct
    (vertex, u, v) of the corners, in the order corners first use them (face 0's corners first).

    vmapping (N',) int64: the mapping's vertex (of .mesh) each new vertex copies; indices (F, 3)
    int64: the faces over the new vertices; uvs (N', 2) float64. A vertex is split where its
    corners' UVs differ (a seam, a chart's border); corners with the same UV share one vertex.
    Invalid corners have UV (0, 0) (.state says which) and share as any other."""
    triangles = self.mesh.triangles.reshape(-1).astype(_np.float64)
    uv = self.uv.reshape(-1, 2)
    keys = _np.column_stack([triangles, uv])
    corner_vertex, first = _corner_keys(keys)
    vmapping = self.mesh.triangles.reshape(-1)[first].astype(_np.int64)
    return vmapping, corner_vertex.reshape(-1, 3).astype(_np.int64), uv[first].copy()


def _to_arrays(self):
    """(V, F, TC, FTC) in libigl's layout: V (N, 3) float64 the positions (a view, no copy), F (F, 3)
    int64, TC (T, 2) float64 the distinct UVs in the order corners first use them, FTC (F, 3) int64
    the corners' rows of TC. Corner k of face f has UV TC[FTC[f, k]] == m.uv[f, k]."""
    uv = self.uv.reshape(-1, 2)
    ftc, first = _corner_keys(uv)
    return (self.mesh.positions, self.mesh.triangles.astype(_np.int64), uv[first].copy(),
            ftc.reshape(-1, 3).astype(_np.int64))


def _from_arrays(V, F, TC=None, FTC=None):
    """A Mesh from libigl's layout: V (N, 3), F (F, 3), and optionally TC (T, 2) with FTC (F, 3)
    indices into TC per corner (FTC defaults to F: one texture vertex per vertex). The corners'
    UVs become the mesh's own (Mesh.uv == TC[FTC])."""
    if TC is None:
        if FTC is not None:
            raise ValueError("from_arrays: FTC without TC")
        return _uvtk.Mesh(V, F)
    TC = _np.asarray(TC, dtype=_np.float64)
    if TC.ndim != 2 or TC.shape[1] < 2:
        raise ValueError(f"from_arrays: TC: expected an array of shape (T, 2), got {TC.shape}")
    FTC = _np.asarray(F if FTC is None else FTC)
    if FTC.dtype.kind not in "iu":
        raise TypeError(f"from_arrays: FTC: expected an integer array, found dtype {FTC.dtype}")
    faces = _np.asarray(F)
    if FTC.shape != faces.shape:
        raise ValueError(f"from_arrays: FTC: expected the shape of F {faces.shape}, got {FTC.shape}")
    if FTC.size and (FTC.min() < 0 or FTC.max() >= len(TC)):
        raise ValueError(f"from_arrays: FTC: an index outside TC's {len(TC)} rows")
    return _uvtk.Mesh(V, F, uv=TC[:, :2][FTC])


def to_meshio(m):
    """A meshio.Mesh of a Mapping (its split layout: points, int32 triangles, point_data "s" and
    "t", as uvtk's PLY files hold them) or of a Mesh (its own UVs split as a mapping's are)."""
    import meshio

    if isinstance(m, _uvtk.Mesh):
        if m.uv is None:
            return meshio.Mesh(m.positions.copy(), [("triangle", m.triangles.copy())])
        m = _uvtk.file_uvs(m)
    vmapping, indices, uvs = m.split()
    return meshio.Mesh(m.mesh.positions[vmapping], [("triangle", indices.astype(_np.int32))],
                       point_data={"s": uvs[:, 0].copy(), "t": uvs[:, 1].copy()})


def from_meshio(mesh):
    """A Mesh of a meshio.Mesh's triangles (other cells are left out; a mesh without triangles is a
    ValueError), with per-vertex UVs as the corners' UVs where its point_data has them: "s" and "t"
    (uvtk's PLY), "u" and "v", "texture_u" and "texture_v", or "uv" (N, 2)."""
    triangles = [block.data for block in mesh.cells if block.type == "triangle"]
    if not triangles:
        raise ValueError("from_meshio: the mesh has no triangles")
    faces = _np.concatenate(triangles).astype(_np.int64)
    data = mesh.point_data
    uv = None
    if "uv" in data:
        uv = _np.asarray(data["uv"], dtype=_np.float64)[:, :2]
    else:
        for u, v in (("s", "t"), ("u", "v"), ("texture_u", "texture_v")):
            if u in data and v in data:
                uv = _np.column_stack([data[u], data[v]]).astype(_np.float64)
                break
    positions = _np.asarray(mesh.points, dtype=_np.float64)
    if positions.shape[1] == 2:
        positions = _np.column_stack([positions, _np.zeros(len(positions))])
    return _from_arrays(positions, faces, uv, None if uv is None else faces)


_uvtk.Mapping.split = _split
_uvtk.Mapping.to_arrays = _to_arrays
_uvtk.Mesh.from_arrays = staticmethod(_from_arrays)
