"""Many meshes on Dask (docs/python.md, "Many meshes on Dask").

map_many(paths, out_dir, client=None, **options) maps every mesh as `uvtk map DIR -o OUT_DIR`
does, in tasks of a few meshes: OUT_DIR/STEM.obj (or .ply, .glb, .gltf) with the same bytes, each mesh
mapped with threads=1 unless given (the tasks are the parallelism, as `--jobs` is the program's).
Where the tasks run is Dask's choice: client=None runs them on Dask's default scheduler (a
dask.bag); a distributed.Client runs them on its cluster; a scheduler's address
("tcp://host:8786") connects to it for the call.
"""
import os as _os

__all__ = ["map_many"]

# The extensions `uvtk map DIR` maps (inspect::meshesInFolder).
_MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".gltf", ".glb")


def _meshes(paths):
    if isinstance(paths, (str, bytes, _os.PathLike)):
        folder = _os.fsdecode(paths)
        return sorted(_os.path.join(folder, name) for name in _os.listdir(folder)
                      if name.lower().endswith(_MESH_EXTENSIONS) and _os.path.isfile(_os.path.join(folder, name)))
    return [_os.fsdecode(p) for p in paths]


def _map_one(path, out_dir, extension, options):
    """One task: read, map, write OUT_DIR/STEM.EXT; returns the mesh's record (never raises)."""
    import time

    import uvtk

    start = time.perf_counter()
    stem = _os.path.splitext(_os.path.basename(path))[0]
    output = _os.path.join(out_dir, stem + extension)
    try:
        mesh = uvtk.read_mesh(path)
        m = uvtk.map(mesh, **options)
        # the program's comment line, and its threads (one a mesh in a batch)
        uvtk.write_mesh(output, mesh, m, header="uvtk map " + path, threads=options.get("threads", 1))
    except Exception as error:  # one mesh's failure is the batch's record, as `uvtk map DIR` counts it
        return {"error": f"{type(error).__name__}: {error}", "input": path,
                "milliseconds": (time.perf_counter() - start) * 1e3, "status": "failed"}
    return {"input": path, "milliseconds": (time.perf_counter() - start) * 1e3, "output": output, "status": "ok",
            "summary": m.summary, "verdict": m.verdict["status"]}


_heap_kept = False


def _keep_freed_buffers():
    """Where the environment sets MALLOC_TRIM_THRESHOLD_ (distributed's nanny starts every worker
    with 65536), glibc turns its adaptive mmap threshold off: each buffer over 128 KiB of every mesh
    then comes fresh from the kernel and goes back when freed, and fresh pages cost (about 3 ms a
    megabyte on the 2-core machine of docs/python.md: map_many ran at 0.76x the program's
    throughput). Such a worker process keeps buffers up to 32 MiB in its heap and trims above
    64 MiB, the limits glibc's adaptive threshold reaches (its DEFAULT_MMAP_THRESHOLD_MAX); once a
    process, on glibc only."""
    global _heap_kept
    if _heap_kept or "MALLOC_TRIM_THRESHOLD_" not in _os.environ:
        return
    _heap_kept = True
    import ctypes
    import platform

    if platform.libc_ver()[0] != "glibc":
        return
    mallopt = getattr(ctypes.CDLL(None), "mallopt", None)
    if mallopt is not None:
        M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3  # glibc's malloc.h
        mallopt(M_MMAP_THRESHOLD, 32 << 20)
        mallopt(M_TRIM_THRESHOLD, 64 << 20)


def _map_chunk(paths, out_dir, extension, options):
    """One task of several meshes: fewer tasks for the scheduler to hand out (each costs a few
    milliseconds of its and the workers' event loops), the same records."""
    _keep_freed_buffers()
    return [_map_one(path, out_dir, extension, options) for path in paths]


def _chunks(items, workers):
    """`items` in consecutive chunks, shrinking as they go (each a quarter of a worker's share of
    what is left, down to one mesh): few tasks for the scheduler early, and small ones at the end
    so that no worker idles while another finishes a long chunk."""
    chunks, start = [], 0
    while start < len(items):
        size = max(1, (len(items) - start) // (4 * max(1, workers)))
        chunks.append(items[start:start + size])
        start += size
    return chunks


def map_many(paths, out_dir, client=None, format="obj", **options):  # noqa: A002 (as --format)
    """Maps every mesh of `paths` (a list of files, or a folder: its meshes as `uvtk map DIR` finds
    them) into `out_dir`, in Dask tasks of a few meshes; the keywords are uvtk.map's (threads=1 unless
    given). client: None (Dask's default scheduler over a dask.bag), a distributed.Client, or a
    scheduler's address. Returns the batch as `uvtk map DIR --json` writes batch.json: "mapped",
    "failed", "meshes" [{"input", "status" ("ok" or "failed"), "verdict", "output", "summary" (the
    record itself, as a dict), "error", "milliseconds"}, ...] in the order of the paths,
    "milliseconds" {"wall"}, "options" (the mapping's, as the summaries give them), "tool"; and
    "verdicts" {"pass", "warn", "fail"}."""
    import time

    start = time.perf_counter()
    meshes = _meshes(paths)
    out_dir = _os.fsdecode(out_dir)
    _os.makedirs(out_dir, exist_ok=True)
    extension = "." + format.lower()
    if extension not in (".obj", ".ply", ".glb", ".gltf"):
        raise ValueError(f"map_many: format: '{format}' is not one of obj, ply, glb, gltf")
    options.setdefault("threads", 1)
    import uvtk

    jobs = None
    if client is None:
        import dask.bag

        workers = dask.config.get("num_workers", None) or _os.cpu_count() or 1
        bag = dask.bag.from_sequence(_chunks(meshes, workers), partition_size=1)
        records = [record for chunk in bag.map(_map_chunk, out_dir, extension, options).compute() for record in chunk]
    else:
        own = None
        if isinstance(client, str):
            import distributed

            client = own = distributed.Client(client)
        try:
            jobs = sum(client.nthreads().values())
            futures = client.map(_map_chunk, _chunks(meshes, jobs), out_dir=out_dir, extension=extension,
                                 options=options, pure=False)
            records = [record for chunk in client.gather(futures) for record in chunk]
        finally:
            if own is not None:
                own.close()
    records = list(records)
    verdicts = {"pass": 0, "warn": 0, "fail": 0}
    for record in records:
        if record["status"] == "ok":
            verdicts[record["verdict"]] += 1
    failed = sum(1 for r in records if r["status"] == "failed")
    mapped = [r for r in records if r["status"] == "ok"]
    return {"failed": failed, "jobs": jobs, "mapped": len(records) - failed, "meshes": records,
            "milliseconds": {"wall": (time.perf_counter() - start) * 1e3},
            "options": mapped[0]["summary"].get("options") if mapped else None,
            "tool": {"name": "uvtk", "version": uvtk.__version__}, "verdicts": verdicts}
