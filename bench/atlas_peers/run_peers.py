#!/usr/bin/env python3
"""Runs the atlas peers on a list of meshes and measures their layouts (python3 stdlib only).

    /usr/bin/python3 bench/atlas_peers/run_peers.py --out DIR --xatlas PATH/xatlas_driver \
        --mesh torus_knot=/tmp/lr/torus_knot.obj --mesh cube=meshes/cube.obj ... \
        [--runs 3] [--uvtk-runs 5] [--peers uvtk,blender,blender_fraction4,xatlas,...] \
        [--merge OLD_results.json [--rejudge]] \
        [--results DIR/results.json] [--table DIR/table.md]
    /usr/bin/python3 bench/atlas_peers/run_peers.py --table-from results.json [--per-mesh]

Peers (one heavy job at a time; each run is a fresh process):
  uvtk              `uvtk map IN.obj -o OUT.obj --projector atlas --margin 4 --texture-size 1024
                    --json OUT.map.json -q` (the --uvtk binary); the time is the JSON's
                    milliseconds.map, the atlas alone (not reading, judging or writing)
  uvtk_lscm         the same with --projector lscm (the atlas's charts, each flattened by CGAL's
                    LSCM); uvtk_arap: --projector arap
  blender           Blender's Smart UV Project (blender_smart_project.py beside this file), angle
                    66, island_margin 4/1024, Blender's default margin_method (SCALED)
  blender_fraction  the same with margin_method=FRACTION (the margin as a fraction of the UV square:
                    4/1024 on each side of each island, a gutter of about 8 texels at 1024)
  blender_fraction4 margin_method=FRACTION, island_margin 2/1024: a gutter of about 4 texels, the
                    same as uvtk's --margin 4
  xatlas            an xatlas driver (built by you from jpcy/xatlas; not part of this repository):
                    `DRIVER IN.obj OUT.obj --padding 4 --resolution 1024`, ChartOptions defaults
  xatlas_nomirror   the same with ChartOptions::fixWinding and PackOptions::rotateCharts = false

The time is the peer's own report of its atlas call alone (Blender: uv.smart_project; xatlas:
Generate; uvtk: milliseconds.map), the median of --runs runs (--uvtk-runs for the uvtk peers); the
whole process's wall time is kept too (process_wall_seconds_median). Each layout is then measured
by layout_stats.py (beside this file, run with --python, whose numpy it needs) and judged by
`uvtk report OUT.obj --json`, the same for every peer, uvtk's own included.
A peer that exits non-zero, dies of a signal or exceeds --timeout is recorded as such and skipped.

--merge OLD.json keeps OLD's rows of the meshes and peers not run now (so only new peers need to
run); with --rejudge those kept rows are measured and judged again (layout_stats.py and `uvtk
report` on their output files; their times are kept), so that every row of the table is counted
by the same script and judged by the same binary.
"""
import argparse
import json
import os
import signal
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


PEER_ORDER = ["uvtk", "uvtk_lscm", "uvtk_arap", "blender", "blender_fraction4", "blender_fraction",
              "xatlas", "xatlas_nomirror"]
UVTK_PROJECTOR = {"uvtk": "atlas", "uvtk_lscm": "lscm", "uvtk_arap": "arap"}


def map_json_path(dst):
    return dst[:-len(".obj")] + ".map.json" if dst.endswith(".obj") else dst + ".map.json"


def peer_command(peer, args, src, dst):
    if peer in UVTK_PROJECTOR:
        return [args.uvtk, "map", src, "-o", dst, "--projector", UVTK_PROJECTOR[peer], "--margin", "4",
                "--texture-size", "1024", "--json", map_json_path(dst), "-q"]
    if peer.startswith("blender"):
        margin = "2" if peer == "blender_fraction4" else "4"
        cmd = [args.blender, "-b", "--factory-startup", "--python",
               os.path.join(HERE, "blender_smart_project.py"), "--", src, dst,
               "--angle-limit", "66", "--margin-texels", margin, "--texture-size", "1024"]
        if peer in ("blender_fraction", "blender_fraction4"):
            cmd += ["--margin-method", "FRACTION"]
        if args.position_tolerance is not None:
            cmd += ["--position-tolerance", repr(args.position_tolerance)]
        return cmd
    cmd = [args.xatlas, src, dst, "--padding", "4", "--resolution", "1024"]
    if peer == "xatlas_nomirror":
        cmd += ["--fix-winding", "--no-rotate-charts"]
    return cmd


def uvtk_map_report(json_path):
    """uvtk map's own JSON, reduced to the peer report: seconds = milliseconds.map / 1000."""
    with open(json_path) as f:
        j = json.load(f)
    return {"seconds": j["milliseconds"]["map"] / 1000.0, "milliseconds": j["milliseconds"],
            "atlas": j.get("atlas"), "verdict": j.get("verdict"), "faces": j.get("faces")}


def run_peer(cmd, timeout, uvtk_json=None):
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout after %g s" % timeout, time.perf_counter() - t0
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        if p.returncode < 0:
            try:
                why = "killed by signal %d (%s)" % (-p.returncode, signal.Signals(-p.returncode).name)
            except ValueError:
                why = "killed by signal %d" % -p.returncode
        else:
            why = "exit %d" % p.returncode
        tail = (p.stderr.strip().splitlines() or [""])[-1][:300]
        return None, ("%s: %s" % (why, tail)) if tail else why, wall
    if uvtk_json:
        try:
            return uvtk_map_report(uvtk_json), None, wall
        except (OSError, ValueError, KeyError) as e:
            return None, "no usable --json from uvtk map: %s" % e, wall
    for line in p.stdout.splitlines():
        if line.startswith('{"seconds"'):
            return json.loads(line), None, wall
    return None, "no JSON line in the output", wall


def stats(args, obj, texture_size, overlap=True):
    cmd = [args.python, os.path.join(HERE, "layout_stats.py"), obj, "--texture-size", texture_size]
    if not overlap:
        cmd.append("--no-overlap")
    return json.loads(subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout)


def uvtk_report(args, obj, json_path):
    p = subprocess.run([args.uvtk, "report", obj, "--json", json_path], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    with open(json_path) as f:
        r = json.load(f)
    return {
        "summary": p.stdout.strip().splitlines()[-1] if p.stdout.strip() else "",
        "verdict": r.get("verdict"),
        "reasons": [x.get("text") for x in r.get("reasons", [])],
        "stretch_l2": r.get("stretch_l2"),
        "stretch_linf": r.get("stretch_linf"),
        "overlap_fraction": r.get("overlap_fraction"),
        "rule_values": r.get("rule_values"),
    }


def fmt(x, nd=3):
    if x is None:
        return "-"
    if isinstance(x, float):
        return ("%%.%dg" % nd) % x if abs(x) < 1e4 else "%.0f" % x
    return str(x)


def fmt_ms(seconds):
    ms = seconds * 1000.0
    return "%.0f" % ms if ms >= 100 else "%.3g" % ms


def table(results):
    rows = ["| mesh | faces | peer | time s (median) | charts | occupancy | seam length | gutter texels @1024 "
            "(native) | flipped faces (UV area) | overlap (est.) | uvtk L2 stretch | uvtk verdict |",
            "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in results:
        if r.get("error"):
            rows.append("| %s | %s | %s | %s | | | | | | | | %s |" % (
                r["mesh"], r.get("faces", ""), r["peer"], "-", "**" + r["error"] + "**"))
            continue
        s = r["stats"]
        g = fmt(s.get("gutter_texels"))
        if r.get("native_gutter_texels") is not None:
            g += " (%s @%dx%d)" % (fmt(r["native_gutter_texels"]), r["native_size"][0], r["native_size"][1])
        verdict = r["uvtk"]["verdict"]
        if r["uvtk"]["reasons"]:
            verdict += ": " + "; ".join(r["uvtk"]["reasons"])
        rows.append("| %s | %d | %s | %s | %d | %s | %s | %s | %d (%s) | %s | %s | %s |" % (
            r["mesh"], s["faces"], r["peer"], fmt(r["seconds_median"]), s["charts"], fmt(s["occupancy"]),
            fmt(s["seam_length"], 4), g, s["flipped_faces"], fmt(s["flipped_uv_area"]),
            fmt(s.get("overlap_fraction")), fmt(r["uvtk"]["stretch_l2"], 4), verdict))
    return "\n".join(rows) + "\n"


def per_mesh_tables(results, peers=None):
    """One compact table per mesh: time (atlas call only, ms), charts, occupancy, seam length, gutter,
    flipped faces, uvtk verdict; all but the time from layout_stats.py and `uvtk report`."""
    if peers:
        results = [r for r in results if r["peer"] in peers]
    out, meshes = [], []
    for r in results:
        if r["mesh"] not in meshes:
            meshes.append(r["mesh"])
    for m in meshes:
        rows = [r for r in results if r["mesh"] == m]
        out.append("%s, %s faces\n" % (m, "{:,}".format(rows[0]["faces"])))
        out.append("| peer | time ms | charts | occupancy | seam length | gutter texels | flipped faces | uvtk verdict |")
        out.append("|---|---:|---:|---:|---:|---:|---:|---|")
        for r in sorted(rows, key=lambda r: PEER_ORDER.index(r["peer"]) if r["peer"] in PEER_ORDER else 99):
            if r.get("error"):
                out.append("| %s | - | | | | | | **%s** |" % (r["peer"], r["error"]))
                continue
            s = r["stats"]
            verdict = r["uvtk"]["verdict"]
            if r["uvtk"]["reasons"]:
                verdict += ": " + "; ".join(x.split(" (")[0] for x in r["uvtk"]["reasons"])
            out.append("| %s | %s | %d | %s | %s | %s | %d | %s |" % (
                r["peer"], fmt_ms(r["seconds_median"]), s["charts"], fmt(s["occupancy"]),
                fmt(s["seam_length"], 4), fmt(s.get("gutter_texels")), s["flipped_faces"], verdict))
        out.append("")
    return "\n".join(out)


def order_key(meshes):
    def key(r):
        mi = meshes.index(r["mesh"]) if r["mesh"] in meshes else len(meshes)
        pi = PEER_ORDER.index(r["peer"]) if r["peer"] in PEER_ORDER else len(PEER_ORDER)
        return (mi, pi)
    return key


def judge(args, rec, name, peer):
    dst = rec["output"]
    rec["stats"] = stats(args, dst, "1024,1024")
    if peer.startswith("xatlas"):
        w, h = rec["peer_report"]["width"], rec["peer_report"]["height"]
        rec["native_size"] = [w, h]
        rec["native_gutter_texels"] = stats(args, dst, "%d,%d" % (w, h), overlap=False)["gutter_texels"]
    rec["uvtk"] = uvtk_report(args, dst, os.path.join(args.out, "%s.%s.report.json" % (name, peer)))
    rec["judged_by"] = {"uvtk": args.uvtk, "layout_stats": os.path.join(HERE, "layout_stats.py")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", help="folder for the peers' OBJ files and reports")
    ap.add_argument("--mesh", action="append", default=[], help="NAME=PATH (repeatable)")
    ap.add_argument("--peers", default="blender,xatlas,blender_fraction,xatlas_nomirror")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--uvtk-runs", type=int, default=5, help="runs of the uvtk peers")
    ap.add_argument("--merge", default=None, metavar="OLD_RESULTS_JSON",
                    help="keep OLD's rows of the (mesh, peer) pairs not run now")
    ap.add_argument("--rejudge", action="store_true",
                    help="with --merge: run layout_stats.py and uvtk report again on the kept rows")
    ap.add_argument("--per-mesh", nargs="?", const="", default=None, metavar="PEERS",
                    help="with --table-from: one compact table per mesh (of these comma-separated peers)")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per peer run")
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--position-tolerance", type=float, default=None,
                    help="Blender's check of the positions it wrote back (default 1e-6): a mesh whose "
                         "coordinates reach 80 loses 4e-6 to float32 and %%.6f")
    ap.add_argument("--xatlas", default=None, help="the xatlas driver binary")
    ap.add_argument("--uvtk", default=os.path.join(REPO, "build", "apps", "uvtk", "uvtk"))
    ap.add_argument("--python", default="/usr/bin/python3", help="a python3 with numpy")
    ap.add_argument("--results", default=None, help="JSON file (default OUT/results.json)")
    ap.add_argument("--table", default=None, help="markdown file (default OUT/table.md)")
    ap.add_argument("--table-from", default=None, metavar="RESULTS_JSON",
                    help="only print the markdown table of an earlier run's results")
    args = ap.parse_args()
    if args.table_from:
        with open(args.table_from) as f:
            res = json.load(f)
        if args.per_mesh is not None:
            sys.stdout.write(per_mesh_tables(res, [p for p in args.per_mesh.split(",") if p]))
        else:
            sys.stdout.write(table(res))
        return
    if not args.out:
        sys.exit("--out DIR is needed")
    os.makedirs(args.out, exist_ok=True)
    peers = [p for p in args.peers.split(",") if p]
    if any(p.startswith("xatlas") for p in peers) and not args.xatlas:
        sys.exit("--xatlas DRIVER is needed for the xatlas peers")
    results_path = args.results or os.path.join(args.out, "results.json")
    table_path = args.table or os.path.join(args.out, "table.md")
    results = []
    mesh_names = [spec.split("=", 1)[0] for spec in args.mesh]
    kept = []
    if args.merge:
        with open(args.merge) as f:
            old = json.load(f)
        kept = [r for r in old if not (r["mesh"] in mesh_names and r["peer"] in peers)]
        for r in kept:
            if args.rejudge and not r.get("error") and os.path.exists(r.get("output", "")):
                before = (r["stats"]["charts"], r["stats"]["occupancy"], r["stats"].get("gutter_texels"),
                          r["uvtk"]["verdict"])
                judge(args, r, r["mesh"], r["peer"])
                after = (r["stats"]["charts"], r["stats"]["occupancy"], r["stats"].get("gutter_texels"),
                         r["uvtk"]["verdict"])
                r["rejudged"] = True
                print("%-16s %-17s rejudged%s" % (r["mesh"], r["peer"],
                      "" if before == after else " (was %s, now %s)" % (before, after)),
                      file=sys.stderr, flush=True)
        results.extend(kept)
        mesh_names += [r["mesh"] for r in kept if r["mesh"] not in mesh_names]

    def save():
        with open(results_path, "w") as f:
            json.dump(sorted(results, key=order_key(mesh_names)), f, indent=1)

    for spec in args.mesh:
        name, path = spec.split("=", 1)
        nfaces = sum(1 for line in open(path) if line.startswith("f "))
        for peer in peers:
            dst = os.path.join(args.out, "%s.%s.obj" % (name, peer))
            rec = {"mesh": name, "input": path, "faces": nfaces, "peer": peer,
                   "command": " ".join(peer_command(peer, args, path, dst))}
            times, walls, last = [], [], None
            is_uvtk = peer in UVTK_PROJECTOR
            for _ in range(args.uvtk_runs if is_uvtk else args.runs):
                if is_uvtk and os.path.exists(map_json_path(dst)):
                    os.remove(map_json_path(dst))
                out, err, wall = run_peer(peer_command(peer, args, path, dst), args.timeout,
                                          uvtk_json=map_json_path(dst) if is_uvtk else None)
                if err:
                    rec["error"] = err
                    rec["wall_seconds"] = wall
                    break
                times.append(out["seconds"])
                walls.append(wall)
                last = out
            print("%-16s %-17s %s" % (name, peer, rec.get("error") or "%.4g s (process %.3g s)" % (
                  statistics.median(times), statistics.median(walls))), file=sys.stderr, flush=True)
            if rec.get("error"):
                results.append(rec)
                save()
                continue
            rec["seconds_runs"] = times
            rec["seconds_median"] = statistics.median(times)
            rec["process_wall_seconds_runs"] = walls
            rec["process_wall_seconds_median"] = statistics.median(walls)
            rec["peer_report"] = last
            rec["output"] = dst
            judge(args, rec, name, peer)
            results.append(rec)
            save()
    results.sort(key=order_key(mesh_names))
    save()
    with open(table_path, "w") as f:
        f.write(table(results))
    sys.stdout.write(table(results))


if __name__ == "__main__":
    main()
