#!/usr/bin/env python3
"""Runs the atlas peers on a list of meshes and measures their layouts (python3 stdlib only).

    /usr/bin/python3 bench/atlas_peers/run_peers.py --out DIR --xatlas PATH/xatlas_driver \
        --mesh torus_knot=/tmp/lr/torus_knot.obj --mesh cube=meshes/cube.obj ... \
        [--runs 3] [--peers blender,xatlas,blender_fraction,xatlas_nomirror] \
        [--results DIR/results.json] [--table DIR/table.md]

Peers (one heavy job at a time; each run is a fresh process):
  blender           Blender's Smart UV Project (blender_smart_project.py beside this file), angle
                    66, island_margin 4/1024, Blender's default margin_method (SCALED)
  blender_fraction  the same with margin_method=FRACTION (the margin as a fraction of the UV square)
  xatlas            an xatlas driver (built by you from jpcy/xatlas; not part of this repository):
                    `DRIVER IN.obj OUT.obj --padding 4 --resolution 1024`, ChartOptions defaults
  xatlas_nomirror   the same with ChartOptions::fixWinding and PackOptions::rotateCharts = false

The time is the peer's own report of its atlas call alone (Blender: uv.smart_project; xatlas:
Generate), the median of --runs runs. Each layout is then measured by layout_stats.py (beside this
file, run with --python, whose numpy it needs) and judged by `uvtk report OUT.obj --json`.
A peer that exits non-zero, dies of a signal or exceeds --timeout is recorded as such and skipped.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


def peer_command(peer, args, src, dst):
    if peer.startswith("blender"):
        cmd = [args.blender, "-b", "--factory-startup", "--python",
               os.path.join(HERE, "blender_smart_project.py"), "--", src, dst,
               "--angle-limit", "66", "--margin-texels", "4", "--texture-size", "1024"]
        if peer == "blender_fraction":
            cmd += ["--margin-method", "FRACTION"]
        return cmd
    cmd = [args.xatlas, src, dst, "--padding", "4", "--resolution", "1024"]
    if peer == "xatlas_nomirror":
        cmd += ["--fix-winding", "--no-rotate-charts"]
    return cmd


def run_peer(cmd, timeout):
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout after %g s" % timeout, time.perf_counter() - t0
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        why = ("killed by signal %d" % -p.returncode) if p.returncode < 0 else ("exit %d" % p.returncode)
        tail = (p.stderr.strip().splitlines() or [""])[-1][:300]
        return None, "%s: %s" % (why, tail), wall
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


def table(results):
    rows = ["| mesh | faces | peer | time s (median) | charts | occupancy | seam length | gutter texels @1024 "
            "(native) | flipped faces (UV area) | overlap (est.) | uvtk verdict |",
            "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in results:
        if r.get("error"):
            rows.append("| %s | %s | %s | %s | | | | | | | %s |" % (
                r["mesh"], r.get("faces", ""), r["peer"], "-", "**" + r["error"] + "**"))
            continue
        s = r["stats"]
        g = fmt(s.get("gutter_texels"))
        if r.get("native_gutter_texels") is not None:
            g += " (%s @%dx%d)" % (fmt(r["native_gutter_texels"]), r["native_size"][0], r["native_size"][1])
        verdict = r["uvtk"]["verdict"]
        if r["uvtk"]["reasons"]:
            verdict += ": " + "; ".join(r["uvtk"]["reasons"])
        rows.append("| %s | %d | %s | %s | %d | %s | %s | %s | %d (%s) | %s | %s |" % (
            r["mesh"], s["faces"], r["peer"], fmt(r["seconds_median"]), s["charts"], fmt(s["occupancy"]),
            fmt(s["seam_length"], 4), g, s["flipped_faces"], fmt(s["flipped_uv_area"]),
            fmt(s.get("overlap_fraction")), verdict))
    return "\n".join(rows) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, help="folder for the peers' OBJ files and reports")
    ap.add_argument("--mesh", action="append", default=[], help="NAME=PATH (repeatable)")
    ap.add_argument("--peers", default="blender,xatlas,blender_fraction,xatlas_nomirror")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per peer run")
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--xatlas", default=None, help="the xatlas driver binary")
    ap.add_argument("--uvtk", default=os.path.join(REPO, "build", "apps", "uvtk", "uvtk"))
    ap.add_argument("--python", default="/usr/bin/python3", help="a python3 with numpy")
    ap.add_argument("--results", default=None, help="JSON file (default OUT/results.json)")
    ap.add_argument("--table", default=None, help="markdown file (default OUT/table.md)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    peers = [p for p in args.peers.split(",") if p]
    if any(p.startswith("xatlas") for p in peers) and not args.xatlas:
        sys.exit("--xatlas DRIVER is needed for the xatlas peers")
    results_path = args.results or os.path.join(args.out, "results.json")
    table_path = args.table or os.path.join(args.out, "table.md")
    results = []
    for spec in args.mesh:
        name, path = spec.split("=", 1)
        nfaces = sum(1 for line in open(path) if line.startswith("f "))
        for peer in peers:
            dst = os.path.join(args.out, "%s.%s.obj" % (name, peer))
            rec = {"mesh": name, "input": path, "faces": nfaces, "peer": peer,
                   "command": " ".join(peer_command(peer, args, path, dst))}
            times, walls, last = [], [], None
            for _ in range(args.runs):
                out, err, wall = run_peer(peer_command(peer, args, path, dst), args.timeout)
                if err:
                    rec["error"] = err
                    rec["wall_seconds"] = wall
                    break
                times.append(out["seconds"])
                walls.append(wall)
                last = out
            print("%-16s %-17s %s" % (name, peer, rec.get("error") or "%.3f s" % statistics.median(times)),
                  file=sys.stderr, flush=True)
            if rec.get("error"):
                results.append(rec)
                continue
            rec["seconds_runs"] = times
            rec["seconds_median"] = statistics.median(times)
            rec["process_wall_seconds_median"] = statistics.median(walls)
            rec["peer_report"] = last
            rec["output"] = dst
            rec["stats"] = stats(args, dst, "1024,1024")
            if peer.startswith("xatlas"):
                w, h = last["width"], last["height"]
                rec["native_size"] = [w, h]
                rec["native_gutter_texels"] = stats(args, dst, "%d,%d" % (w, h), overlap=False)["gutter_texels"]
            rec["uvtk"] = uvtk_report(args, dst, os.path.join(args.out, "%s.%s.report.json" % (name, peer)))
            results.append(rec)
            with open(results_path, "w") as f:
                json.dump(results, f, indent=1)
    with open(results_path, "w") as f:
        json.dump(results, f, indent=1)
    with open(table_path, "w") as f:
        f.write(table(results))
    sys.stdout.write(table(results))


if __name__ == "__main__":
    main()
