#!/usr/bin/env python3
"""Independent recount of a UV atlas stored in an OBJ file (python3 + numpy only).

    python3 bench/atlas_peers/layout_stats.py OUT.obj [--texture-size 1024,1024]
                                                      [--overlap-resolution 2048]

Reads `v`, `vt` and triangular `f v/vt[/vn]` lines (one UV per face corner) and prints one JSON
object:

  faces, vertices     counts from the file
  charts              UV-connected components: two faces sharing a mesh edge (same two `v`
                      indices) are in one chart when the edge's two endpoints have equal UVs in
                      both faces (|du|, |dv| <= 1e-9)
  occupancy           sum over faces of |signed UV area| (the unit square has area 1); faces that
                      overlap are counted twice, UVs outside [0,1]^2 are counted too: see
                      uv_outside_corners and uv_bbox
  flipped_faces       faces whose signed UV area is negative (for a consistently oriented mesh a
                      layout without mirroring has every face CCW, i.e. positive);
  flipped_uv_area     and their summed |UV area|
  degenerate_uv_faces faces whose UV area is exactly 0
  seam_length         object-space length of the mesh edges whose faces disagree on the UV of an
                      endpoint (boundary edges, with one face, count nothing: see boundary_length)
  gutter_texels       the smallest distance, in texels of a W x H texture, between two triangles
                      of different charts (0 when they touch or overlap). Exact up to floating
                      point: the distance between two charts that do not overlap is the distance
                      between their outlines (chart-boundary edges, plus interior edges where the
                      faces' orientations differ, i.e. folds), found with a uniform grid whose
                      search radius grows until a pair is found within it; overlap of a whole
                      chart inside another is found by a point-in-triangle test.
  overlap_fraction    ESTIMATE: of the texel centres of a R x R raster of [0,1]^2 (R = 2048 by
                      default) covered by at least one face, the fraction covered by two or more
                      (top-left fill rule, so faces sharing an edge do not count twice). Area
                      outside [0,1]^2 is not rasterized.
"""
import argparse
import json
import math
import sys
import time

import numpy as np

UV_EPS = 1e-9


# ----------------------------------------------------------------------------------------------
# OBJ reading
# ----------------------------------------------------------------------------------------------
def read_obj(path):
    v_lines, vt_lines, f_lines = [], [], []
    with open(path, "r") as fh:
        for line in fh:
            c = line[:3]
            if c == "v  " or c.startswith("v ") or c.startswith("v\t"):
                v_lines.append(line[2:])
            elif c.startswith("vt ") or c.startswith("vt\t"):
                vt_lines.append(line[3:])
            elif c.startswith("f ") or c.startswith("f\t"):
                f_lines.append(line[2:])
    V = _floats(v_lines, 3, "v")
    VT = _floats(vt_lines, 2, "vt")
    F, FT = _faces(f_lines, len(V), len(VT))
    return V, VT, F, FT


def _floats(lines, k, what):
    if not lines:
        return np.zeros((0, k))
    rows = [ln.split()[:k] for ln in lines]
    if any(len(r) < k for r in rows):
        raise SystemExit("a '%s' line has fewer than %d numbers" % (what, k))
    return np.array(rows, dtype=np.float64)


def _faces(lines, nv, nvt):
    if not lines:
        raise SystemExit("no faces")
    toks = [ln.split() for ln in lines]
    bad = [i for i, t in enumerate(toks) if len(t) != 3]
    if bad:
        raise SystemExit("face %d has %d corners: only triangles are measured" % (bad[0], len(toks[bad[0]])))
    F = np.empty((len(toks), 3), dtype=np.int64)
    FT = np.empty((len(toks), 3), dtype=np.int64)
    for i, t in enumerate(toks):
        for k in range(3):
            parts = t[k].split("/")
            if len(parts) < 2 or parts[1] == "":
                raise SystemExit("face %d corner %d has no texture coordinate (need f v/vt)" % (i, k))
            F[i, k] = int(parts[0])
            FT[i, k] = int(parts[1])
    F = np.where(F > 0, F - 1, nv + F)      # OBJ: 1-based, negative = relative
    FT = np.where(FT > 0, FT - 1, nvt + FT)
    if F.min() < 0 or F.max() >= nv or FT.min() < 0 or FT.max() >= nvt:
        raise SystemExit("face index out of range")
    return F, FT


# ----------------------------------------------------------------------------------------------
# Union-find on arrays (hook roots to smaller roots, then compress), for chart labels
# ----------------------------------------------------------------------------------------------
def components(n, a, b):
    parent = np.arange(n, dtype=np.int64)
    a = np.asarray(a, dtype=np.int64)
    b = np.asarray(b, dtype=np.int64)
    while True:
        while True:  # full path compression: parent[x] is a root
            pp = parent[parent]
            if np.array_equal(pp, parent):
                break
            parent = pp
        ra, rb = parent[a], parent[b]
        keep = ra != rb
        if not keep.any():
            break
        a, b, ra, rb = a[keep], b[keep], ra[keep], rb[keep]
        lo, hi = np.minimum(ra, rb), np.maximum(ra, rb)
        parent[hi] = lo  # roots only; any lo < hi is a valid hook, so duplicate writes are fine
    _, labels = np.unique(parent, return_inverse=True)
    return labels


# ----------------------------------------------------------------------------------------------
# Edges: charts, seams, outlines
# ----------------------------------------------------------------------------------------------
def edge_analysis(V, F, UV, sign):
    """UV[f, k] is the UV of corner k of face f. Returns chart labels, seam/boundary figures and
    the outline half-edges (face, corner k: edge from corner k to k+1) used for the gutter."""
    nf = len(F)
    nv = len(V)
    k0 = np.tile(np.arange(3), nf)
    k1 = (k0 + 1) % 3
    fid = np.repeat(np.arange(nf), 3)
    a = F[fid, k0]
    b = F[fid, k1]
    ua = UV[fid, k0]
    ub = UV[fid, k1]
    swap = a > b
    lo = np.where(swap, b, a)
    hi = np.where(swap, a, b)
    uvlo = np.where(swap[:, None], ub, ua)
    uvhi = np.where(swap[:, None], ua, ub)
    key = lo * np.int64(nv) + hi
    order = np.argsort(key, kind="stable")
    key_s = key[order]
    start = np.flatnonzero(np.r_[True, key_s[1:] != key_s[:-1]])
    size = np.diff(np.r_[start, len(key_s)])

    def same_uv(i, j):  # half-edge indices (unsorted numbering)
        return (np.all(np.abs(uvlo[i] - uvlo[j]) <= UV_EPS, axis=-1)
                & np.all(np.abs(uvhi[i] - uvhi[j]) <= UV_EPS, axis=-1))

    matched = np.zeros(3 * nf, dtype=bool)  # half-edge has a UV-equal partner
    join_a, join_b = [], []
    seam_edge = []       # one representative half-edge per seam edge
    # Manifold edges (two faces)
    s2 = start[size == 2]
    i, j = order[s2], order[s2 + 1]
    eq = same_uv(i, j)
    join_a.append(fid[i[eq]])
    join_b.append(fid[j[eq]])
    matched[i[eq]] = True
    matched[j[eq]] = True
    seam_edge.append(i[~eq])
    # Folds: interior edges whose faces have different orientation are outlines too
    fold = eq & (sign[fid[i]] != sign[fid[j]])
    fold_edges = i[fold]
    # Non-manifold edges (three or more faces): all pairs
    nonmanifold = 0
    for s, z in zip(start[size > 2], size[size > 2]):
        nonmanifold += 1
        idx = order[s:s + z]
        disagree = False
        for p in range(z):
            for q in range(p + 1, z):
                if same_uv(idx[p], idx[q]):
                    join_a.append(np.array([fid[idx[p]]]))
                    join_b.append(np.array([fid[idx[q]]]))
                    matched[idx[p]] = matched[idx[q]] = True
                    if sign[fid[idx[p]]] != sign[fid[idx[q]]]:
                        fold_edges = np.r_[fold_edges, idx[p]]
                else:
                    disagree = True
        if disagree:
            seam_edge.append(np.array([idx[0]]))
    labels = components(nf, np.concatenate(join_a), np.concatenate(join_b))
    seam_edge = np.concatenate(seam_edge).astype(np.int64)
    elen = lambda h: np.linalg.norm(V[hi[h]] - V[lo[h]], axis=1)
    boundary = order[start[size == 1]]
    outline = np.r_[np.flatnonzero(~matched), fold_edges].astype(np.int64)
    return {
        "labels": labels,
        "seam_length": float(elen(seam_edge).sum()),
        "seam_edges": int(len(seam_edge)),
        "boundary_length": float(elen(boundary).sum()),
        "boundary_edges": int(len(boundary)),
        "nonmanifold_edges": int(nonmanifold),
        "outline_face": fid[outline],
        "outline_k": k0[outline],
    }


# ----------------------------------------------------------------------------------------------
# Gutter: exact minimum distance between different charts (texel space)
# ----------------------------------------------------------------------------------------------
def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _point_seg_dist2(px, py, ax, ay, bx, by):
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.where(L2 > 0, ((px - ax) * dx + (py - ay) * dy) / np.where(L2 > 0, L2, 1), 0.0)
    t = np.clip(t, 0.0, 1.0)
    qx, qy = ax + t * dx - px, ay + t * dy - py
    return qx * qx + qy * qy


def _seg_seg_dist(P0, P1, Q0, Q1):
    """Vectorized distance between segments P0P1 and Q0Q1 (arrays of shape (n, 2))."""
    p0x, p0y, p1x, p1y = P0[:, 0], P0[:, 1], P1[:, 0], P1[:, 1]
    q0x, q0y, q1x, q1y = Q0[:, 0], Q0[:, 1], Q1[:, 0], Q1[:, 1]
    o1 = _cross(p1x - p0x, p1y - p0y, q0x - p0x, q0y - p0y)
    o2 = _cross(p1x - p0x, p1y - p0y, q1x - p0x, q1y - p0y)
    o3 = _cross(q1x - q0x, q1y - q0y, p0x - q0x, p0y - q0y)
    o4 = _cross(q1x - q0x, q1y - q0y, p1x - q0x, p1y - q0y)
    crossing = (o1 * o2 < 0) & (o3 * o4 < 0)
    d2 = np.minimum.reduce([
        _point_seg_dist2(p0x, p0y, q0x, q0y, q1x, q1y),
        _point_seg_dist2(p1x, p1y, q0x, q0y, q1x, q1y),
        _point_seg_dist2(q0x, q0y, p0x, p0y, p1x, p1y),
        _point_seg_dist2(q1x, q1y, p0x, p0y, p1x, p1y)])
    return np.where(crossing, 0.0, np.sqrt(d2))


def _grid_entries(lo, hi, cell):
    """(cell key, item) for every grid cell that each box [lo, hi] (n x 2) touches."""
    i0 = np.floor(lo / cell).astype(np.int64)
    i1 = np.floor(hi / cell).astype(np.int64)
    nx = i1[:, 0] - i0[:, 0] + 1
    ny = i1[:, 1] - i0[:, 1] + 1
    cnt = nx * ny
    item = np.repeat(np.arange(len(lo)), cnt)
    first = np.repeat(np.cumsum(cnt) - cnt, cnt)
    r = np.arange(cnt.sum()) - first
    ix = i0[item, 0] + r % nx[item]
    iy = i0[item, 1] + r // nx[item]
    key = (ix + (1 << 30)) * (np.int64(1) << 32) + (iy + (1 << 30))
    return key, item


def _cell_pairs(key, item, chart, fn, chunk=4_000_000):
    """Calls fn(i, j) on every pair of items sharing a cell whose charts differ, in chunks."""
    order = np.argsort(key, kind="stable")
    key, item = key[order], item[order]
    start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    size = np.diff(np.r_[start, len(key)])
    # drop cells holding a single chart
    ch = chart[item]
    cmin = np.minimum.reduceat(ch, start)
    cmax = np.maximum.reduceat(ch, start)
    mixed = np.repeat(cmax != cmin, size)
    pos_in = np.arange(len(key)) - np.repeat(start, size)
    gsize = np.repeat(size, size)
    key, item, pos_in, gsize = key[mixed], item[mixed], pos_in[mixed], gsize[mixed]
    n_pairs = 0
    d = 1
    act = np.flatnonzero(pos_in + d < gsize)
    while len(act):
        for c in range(0, len(act), chunk):
            sel = act[c:c + chunk]
            i, j = item[sel], item[sel + d]
            m = chart[i] != chart[j]
            n_pairs += int(m.sum())
            if m.any():
                fn(i[m], j[m])
        d += 1
        act = act[pos_in[act] + d < gsize[act]]
    return n_pairs


def gutter(UVt, labels, outline_face, outline_k, tri_cell=None):
    """UVt: (nf, 3, 2) corner UVs in texel units."""
    nchart = int(labels.max()) + 1 if len(labels) else 0
    if nchart < 2:
        return {"gutter_texels": None, "gutter_note": "fewer than two charts"}
    P0 = UVt[outline_face, outline_k]
    P1 = UVt[outline_face, (outline_k + 1) % 3]
    seg_chart = labels[outline_face]
    ext = float(max(np.ptp(UVt[..., 0]), np.ptp(UVt[..., 1]), 1.0))
    seg_lo = np.minimum(P0, P1)
    seg_hi = np.maximum(P0, P1)
    best = [math.inf, None]

    def take(i, j):
        d = _seg_seg_dist(P0[i], P1[i], P0[j], P1[j])
        k = int(np.argmin(d))
        if d[k] < best[0]:
            best[0] = float(d[k])
            best[1] = (int(seg_chart[i[k]]), int(seg_chart[j[k]]),
                       [float(x) for x in P0[i[k]]], [float(x) for x in P0[j[k]]])

    # 1) whole-chart containment: one outline point per chart tested against other charts' faces
    first_seg = np.unique(seg_chart, return_index=True)[1]
    qpt = P0[first_seg]
    qchart = seg_chart[first_seg]
    tlo = UVt.min(axis=1)
    thi = UVt.max(axis=1)
    if tri_cell is None:
        sizes = np.maximum(thi - tlo, 1e-12).max(axis=1)
        tri_cell = max(float(np.median(sizes)) * 2.0, ext / 4096.0)
    # Insert the faces into the grid (growing the cell while that makes too many entries), keep
    # the entries in cells that hold a query point, and test those faces against those points.
    while True:
        i0 = np.floor(tlo / tri_cell)
        i1 = np.floor(thi / tri_cell)
        if float(((i1 - i0 + 1).prod(axis=1)).sum()) <= 4 * len(UVt) + 1_000_000:
            break
        tri_cell *= 2.0
    qkey, qitem = _grid_entries(qpt, qpt, tri_cell)
    tkey, titem = _grid_entries(tlo, thi, tri_cell)
    keep = np.isin(tkey, qkey)
    tkey, titem = tkey[keep], titem[keep]
    qo = np.argsort(qkey, kind="stable")
    qk, qi = qkey[qo], qitem[qo]
    left = np.searchsorted(qk, tkey, "left")
    cnt = np.searchsorted(qk, tkey, "right") - left
    pairs_t = np.repeat(titem, cnt)
    first = np.repeat(np.cumsum(cnt) - cnt, cnt)
    pairs_q = qi[np.repeat(left, cnt) + (np.arange(int(cnt.sum())) - first)]
    m = labels[pairs_t] != qchart[pairs_q]
    pairs_t, pairs_q = pairs_t[m], pairs_q[m]
    contained = []
    if len(pairs_t):
        A, B, C = UVt[pairs_t, 0], UVt[pairs_t, 1], UVt[pairs_t, 2]
        p = qpt[pairs_q]
        e0 = _cross(B[:, 0] - A[:, 0], B[:, 1] - A[:, 1], p[:, 0] - A[:, 0], p[:, 1] - A[:, 1])
        e1 = _cross(C[:, 0] - B[:, 0], C[:, 1] - B[:, 1], p[:, 0] - B[:, 0], p[:, 1] - B[:, 1])
        e2 = _cross(A[:, 0] - C[:, 0], A[:, 1] - C[:, 1], p[:, 0] - C[:, 0], p[:, 1] - C[:, 1])
        area = _cross(B[:, 0] - A[:, 0], B[:, 1] - A[:, 1], C[:, 0] - A[:, 0], C[:, 1] - A[:, 1])
        inside = (area != 0) & (((e0 >= 0) & (e1 >= 0) & (e2 >= 0)) | ((e0 <= 0) & (e1 <= 0) & (e2 <= 0)))
        if inside.any():
            k = int(np.flatnonzero(inside)[0])
            pt = [float(x) for x in qpt[pairs_q[k]]]
            best = [0.0, (int(qchart[pairs_q[k]]), int(labels[pairs_t[k]]), pt, pt)]
            contained = np.unique(qchart[pairs_q[inside]])
    # 2) outlines: grid with radius r growing fourfold until a pair within r is found
    r = 8.0
    n_pairs_total = 0
    while True:
        cell = r
        key, item = _grid_entries(seg_lo - r / 2, seg_hi + r / 2, cell)
        n_pairs_total += _cell_pairs(key, item, seg_chart, take)
        if best[0] <= r or r > 2 * ext:
            break
        r *= 4.0
    out = {"gutter_texels": best[0] if math.isfinite(best[0]) else None,
           "gutter_search_radius": r, "gutter_pairs_tested": n_pairs_total,
           "outline_segments": int(len(P0))}
    if best[1]:
        out["gutter_between_charts"] = best[1][:2]
        out["gutter_near_texel"] = best[1][2]
    if len(contained):
        out["charts_touching_inside_another"] = int(len(contained))
    return out


# ----------------------------------------------------------------------------------------------
# Overlap estimate: rasterize texel centres of an R x R grid over [0,1]^2
# ----------------------------------------------------------------------------------------------
def overlap_estimate(UV, R):
    A = UV[:, 0] * R
    B = UV[:, 1] * R
    C = UV[:, 2] * R
    area2 = _cross(B[:, 0] - A[:, 0], B[:, 1] - A[:, 1], C[:, 0] - A[:, 0], C[:, 1] - A[:, 1])
    ok = area2 != 0
    # normalise to CCW
    neg = area2 < 0
    Bn = np.where(neg[:, None], C, B)
    Cn = np.where(neg[:, None], B, C)
    A, B, C = A[ok], Bn[ok], Cn[ok]
    lo = np.minimum(np.minimum(A, B), C)
    hi = np.maximum(np.maximum(A, B), C)
    # texel centres x + 0.5 inside [lo, hi]
    x0 = np.clip(np.ceil(lo[:, 0] - 0.5), 0, R).astype(np.int64)
    y0 = np.clip(np.ceil(lo[:, 1] - 0.5), 0, R).astype(np.int64)
    x1 = np.clip(np.floor(hi[:, 0] - 0.5), -1, R - 1).astype(np.int64)
    y1 = np.clip(np.floor(hi[:, 1] - 0.5), -1, R - 1).astype(np.int64)
    w = x1 - x0 + 1
    h = y1 - y0 + 1
    live = (w > 0) & (h > 0)
    counts = np.zeros(R * R, dtype=np.int32)
    span = np.maximum(w, h)
    bucket = np.where(live, np.ceil(np.log2(np.maximum(span, 1))).astype(np.int64), -1)

    def edge_fn(P, Q, px, py):
        # Evaluated with the lexicographically smaller endpoint first, so that two faces sharing
        # an edge get exactly opposite values; then the top-left rule breaks ties.
        Px, Py, Qx, Qy = P[:, 0:1], P[:, 1:2], Q[:, 0:1], Q[:, 1:2]
        pfirst = (Px < Qx) | ((Px == Qx) & (Py < Qy))
        Sx, Sy = np.where(pfirst, Px, Qx), np.where(pfirst, Py, Qy)
        Tx, Ty = np.where(pfirst, Qx, Px), np.where(pfirst, Qy, Py)
        e = _cross(Tx - Sx, Ty - Sy, px - Sx, py - Sy)
        e = np.where(pfirst, e, -e)
        dx, dy = Qx - Px, Qy - Py
        topleft = (dy > 0) | ((dy == 0) & (dx < 0))
        return (e > 0) | ((e == 0) & topleft)

    for bk in np.unique(bucket[bucket >= 0]):
        tris = np.flatnonzero(bucket == bk)
        k = 1 << int(bk)
        per = max(1, 8_000_000 // (k * k))
        oy, ox = np.divmod(np.arange(k * k), k)
        for c in range(0, len(tris), per):
            t = tris[c:c + per]
            px = x0[t, None] + ox[None, :]
            py = y0[t, None] + oy[None, :]
            inb = (px <= x1[t, None]) & (py <= y1[t, None])
            cx = px + 0.5
            cy = py + 0.5
            ins = inb.copy()
            for P, Q in ((A[t], B[t]), (B[t], C[t]), (C[t], A[t])):
                ins &= edge_fn(P, Q, cx, cy)
            idx = (py * R + px)[ins]
            counts += np.bincount(idx, minlength=R * R).astype(np.int32)
    covered = int((counts >= 1).sum())
    multi = int((counts >= 2).sum())
    return {
        "overlap_fraction": multi / covered if covered else 0.0,
        "overlap_texels": multi,
        "covered_texels": covered,
        "overlap_resolution": R,
        "overlap_note": "estimate: texel centres of an R x R raster of [0,1]^2 covered by >= 2 faces / covered by >= 1",
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("obj")
    ap.add_argument("--texture-size", default="1024,1024", help="W,H or N (texels, for the gutter)")
    ap.add_argument("--overlap-resolution", type=int, default=2048)
    ap.add_argument("--no-overlap", action="store_true", help="skip the raster estimate")
    args = ap.parse_args()
    ts = [float(x) for x in args.texture_size.split(",")]
    W, H = (ts[0], ts[0]) if len(ts) == 1 else (ts[0], ts[1])

    t0 = time.perf_counter()
    V, VT, F, FT = read_obj(args.obj)
    t_read = time.perf_counter() - t0
    UV = VT[FT]                                    # (nf, 3, 2)
    e1 = UV[:, 1] - UV[:, 0]
    e2 = UV[:, 2] - UV[:, 0]
    sarea = 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    sign = np.sign(sarea).astype(np.int8)
    out = {"file": args.obj, "faces": int(len(F)), "vertices": int(len(V)), "uv_coords": int(len(VT))}

    ea = edge_analysis(V, F, UV, sign)
    labels = ea.pop("labels")
    out["charts"] = int(labels.max()) + 1
    out["occupancy"] = float(np.abs(sarea).sum())
    corner_uv = UV.reshape(-1, 2)
    outside = (corner_uv < 0) | (corner_uv > 1)
    out["uv_outside_corners"] = int(outside.any(axis=1).sum())
    out["uv_bbox"] = [float(corner_uv[:, 0].min()), float(corner_uv[:, 1].min()),
                      float(corner_uv[:, 0].max()), float(corner_uv[:, 1].max())]
    neg = sarea < 0
    out["flipped_faces"] = int(neg.sum())
    out["flipped_uv_area"] = float(abs(sarea[neg].sum()))
    out["degenerate_uv_faces"] = int((sarea == 0).sum())
    out["flipped_charts"] = int(len(np.unique(labels[neg])))
    ofa, ok_ = ea.pop("outline_face"), ea.pop("outline_k")
    out.update(ea)
    t1 = time.perf_counter()
    scale = np.array([W, H])
    g = gutter(UV * scale, labels, ofa, ok_)
    out["texture_size"] = [W, H]
    out.update(g)
    t2 = time.perf_counter()
    if not args.no_overlap:
        out.update(overlap_estimate(UV, args.overlap_resolution))
    t3 = time.perf_counter()
    out["seconds"] = {"read": round(t_read, 3), "edges": round(t1 - t0 - t_read, 3),
                      "gutter": round(t2 - t1, 3), "overlap": round(t3 - t2, 3)}
    print(json.dumps(out))


if __name__ == "__main__":
    main()
