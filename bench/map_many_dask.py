"""uvtk.map_many on Dask against `uvtk map DIR --jobs N` on the same meshes (docs/python.md, "Many
meshes on Dask"): the wall time of each, the outputs compared byte for byte.

    PYTHONPATH=build/python python3 bench/map_many_dask.py [--meshes 200] [--workers 2] [--rounds 3]

The meshes are lat-long spheres of 24 to 64 segments (--segments) from build/meshes/uvtk_meshgen
(or --folder). Each round times the three in turn, each in a process of its own (a closed
LocalCluster leaves its client's event loop running in the process that made it, which would slow
the threaded scheduler's run after it), after the previous run's output is written back (os.sync);
the medians and ranges are printed.
"""
import argparse
import importlib
import json
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def run_map_many(folder, out_dir, workers, projector, scheduler):
    """One map_many run in this process; prints {"seconds", "start", "mapped"} as JSON."""
    import uvtk

    if scheduler == "threads":
        import dask
        import dask.bag  # imported before the clock, as in a long-running process (map_many imports it)

        start = time.perf_counter()
        with dask.config.set(scheduler="threads", num_workers=workers):
            batch = uvtk.map_many(folder, out_dir, projector=projector)
        print(json.dumps({"seconds": time.perf_counter() - start, "start": 0.0, "mapped": batch["mapped"]}))
        return
    import distributed

    start = time.perf_counter()
    with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        client.run(importlib.import_module, "uvtk")  # as a long-running cluster's workers have
        started = time.perf_counter() - start
        start = time.perf_counter()
        batch = uvtk.map_many(folder, out_dir, client=client, projector=projector)
        seconds = time.perf_counter() - start
    print(json.dumps({"seconds": seconds, "start": started, "mapped": batch["mapped"]}))


def spread(values):
    return f"{statistics.median(values):.2f} s ({min(values):.2f} to {max(values):.2f})"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshes", type=int, default=200)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--projector", default="sphere")
    parser.add_argument("--folder", help="map these meshes instead of generated ones")
    parser.add_argument("--segments", type=int, nargs=2, default=(24, 64), metavar=("MIN", "MAX"),
                        help="the generated spheres' segments (rings: half)")
    parser.add_argument("--uvtk", default="build/apps/uvtk/uvtk")
    parser.add_argument("--meshgen", default="build/meshes/uvtk_meshgen")
    parser.add_argument("--one", nargs=2, metavar=("SCHEDULER", "OUT_DIR"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:
        return run_map_many(args.folder, args.one[1], args.workers, args.projector, args.one[0])
    scratch = pathlib.Path(tempfile.mkdtemp(prefix="uvtk-map-many-"))
    try:
        folder = pathlib.Path(args.folder) if args.folder else scratch / "in"
        if not args.folder:
            folder.mkdir()
            for i in range(args.meshes):
                low, high = args.segments
                segments = low + (i * 7) % (high - low + 1)
                subprocess.run([args.meshgen, "--sphere", str(segments), str(segments // 2), str(folder / f"s{i:03}.obj")],
                               check=True, capture_output=True)
        count = len(list(folder.iterdir()))
        times = {"program": [], "cluster": [], "start": [], "threads": []}
        same = True
        for _ in range(args.rounds):
            shutil.rmtree(scratch / "program", ignore_errors=True)
            start = time.perf_counter()
            subprocess.run([args.uvtk, "map", str(folder), "-o", str(scratch / "program"), "--jobs", str(args.workers),
                            "--projector", args.projector, "-q"], check=True)
            times["program"].append(time.perf_counter() - start)
            os.sync()  # each run starts with no other run's output still to be written back
            for scheduler in ("cluster", "threads"):
                shutil.rmtree(scratch / scheduler, ignore_errors=True)
                out = subprocess.run([sys.executable, __file__, "--folder", str(folder), "--workers", str(args.workers),
                                      "--projector", args.projector, "--one", scheduler, str(scratch / scheduler)],
                                     check=True, capture_output=True, text=True).stdout
                result = json.loads(out.strip().splitlines()[-1])
                assert result["mapped"] == count, result
                times[scheduler].append(result["seconds"])
                os.sync()
                if scheduler == "cluster":
                    times["start"].append(result["start"])
                same &= all((scratch / scheduler / f.name).read_bytes() == f.read_bytes()
                            for f in (scratch / "program").glob("*.obj"))
        program = statistics.median(times["program"])
        print(f"{count} meshes, {args.workers} workers, --projector {args.projector}, {args.rounds} rounds (median, range)")
        print(f"uvtk map DIR --jobs {args.workers}: {spread(times['program'])}")
        print(f"map_many, LocalCluster of {args.workers} processes: {spread(times['cluster'])} "
              f"(+ {statistics.median(times['start']):.2f} s to start it and import uvtk in its workers): "
              f"{program / statistics.median(times['cluster']):.2f}x the program's throughput")
        print(f"map_many, the threaded scheduler ({args.workers} threads): {spread(times['threads'])}: "
              f"{program / statistics.median(times['threads']):.2f}x")
        print(f"outputs byte-equal to the program's: {same}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
