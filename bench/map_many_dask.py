"""uvtk.map_many on Dask against `uvtk map DIR --jobs N` on the same meshes (docs/python.md, "Many
meshes on Dask"): the wall time of each, the outputs compared byte for byte.

    PYTHONPATH=build/python python3 bench/map_many_dask.py [--meshes 200] [--workers 2] [--projector sphere]

The meshes are lat-long spheres of 24 to 64 segments (--segments) from build/meshes/uvtk_meshgen
(or --folder).
"""
import argparse
import os
import pathlib
import shutil
import subprocess
import tempfile
import time

import uvtk


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshes", type=int, default=200)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--projector", default="sphere")
    parser.add_argument("--folder", help="map these meshes instead of generated ones")
    parser.add_argument("--segments", type=int, nargs=2, default=(24, 64), metavar=("MIN", "MAX"),
                        help="the generated spheres' segments (rings: half)")
    parser.add_argument("--uvtk", default="build/apps/uvtk/uvtk")
    parser.add_argument("--meshgen", default="build/meshes/uvtk_meshgen")
    args = parser.parse_args()
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

        start = time.perf_counter()
        subprocess.run([args.uvtk, "map", str(folder), "-o", str(scratch / "program"), "--jobs", str(args.workers),
                        "--projector", args.projector, "-q"], check=True)
        program = time.perf_counter() - start

        import dask
        import distributed

        start = time.perf_counter()
        with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, distributed.Client(cluster) as client:
            started = time.perf_counter() - start
            start = time.perf_counter()
            cluster_batch = uvtk.map_many(folder, scratch / "cluster", client=client, projector=args.projector)
            on_cluster = time.perf_counter() - start

        start = time.perf_counter()
        with dask.config.set(scheduler="threads", num_workers=args.workers):
            threaded_batch = uvtk.map_many(folder, scratch / "threads", projector=args.projector)
        threaded = time.perf_counter() - start

        same = all((scratch / d / f.name).read_bytes() == f.read_bytes()
                   for d in ("cluster", "threads") for f in (scratch / "program").glob("*.obj"))
        assert cluster_batch["mapped"] == threaded_batch["mapped"] == count
        print(f"{count} meshes, {args.workers} workers, --projector {args.projector}")
        print(f"uvtk map DIR --jobs {args.workers}: {program:.2f} s")
        print(f"map_many, LocalCluster of {args.workers} processes: {on_cluster:.2f} s (+ {started:.2f} s to start): "
              f"{program / on_cluster:.2f}x the program's throughput")
        print(f"map_many, the threaded scheduler ({args.workers} threads): {threaded:.2f} s: "
              f"{program / threaded:.2f}x")
        print(f"outputs byte-equal to the program's: {same}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
