"""Many meshes on Dask (docs/python.md, "Many meshes on Dask").

map_many(paths, out_dir, client=None, **options) maps every mesh as `uvtk map DIR -o OUT_DIR`
does, one mesh a task: OUT_DIR/STEM.obj (or .ply, .glb, .gltf) with the same bytes, each mesh
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


def _map_chunk(paths, out_dir, extension, options):
    """One task of several meshes: fewer tasks for the scheduler to hand out (each costs a few
    milliseconds of its and the workers' event loops), the same records."""
    return [_map_one(path, out_dir, extension, options) for path in paths]


def _chunks(items, workers):
    """`items` in consecutive chunks: about 8 a worker, so that uneven meshes still balance."""
    size = max(1, len(items) // (8 * max(1, workers)))
    return [items[i:i + size] for i in range(0, len(items), size)]


def map_many(paths, out_dir, client=None, format="obj", **options):  # noqa: A002 (as --format)
    """Maps every mesh of `paths` (a list of files, or a folder: its meshes as `uvtk map DIR` finds
    them) into `out_dir`, one Dask task a mesh; the keywords are uvtk.map's (threads=1 unless
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

        bag = dask.bag.from_sequence(meshes, partition_size=1)
        records = bag.map(_map_one, out_dir, extension, options).compute()
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
