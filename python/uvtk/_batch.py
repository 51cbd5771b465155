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
    import uvtk

    stem = _os.path.splitext(_os.path.basename(path))[0]
    output = _os.path.join(out_dir, stem + extension)
    try:
        mesh = uvtk.read_mesh(path)
        m = uvtk.map(mesh, **options)
        # the program's comment line, and its threads (one a mesh in a batch)
        uvtk.write_mesh(output, mesh, m, header="uvtk map " + path, threads=options.get("threads", 1))
    except Exception as error:  # one mesh's failure is the batch's record, as `uvtk map DIR` counts it
        return {"input": path, "output": None, "status": "failed", "error": f"{type(error).__name__}: {error}"}
    return {"input": path, "output": output, "status": m.verdict["status"], "summary": m.summary}


def map_many(paths, out_dir, client=None, format="obj", **options):  # noqa: A002 (as --format)
    """Maps every mesh of `paths` (a list of files, or a folder: its meshes as `uvtk map DIR` finds
    them) into `out_dir`, one Dask task a mesh; the keywords are uvtk.map's (threads=1 unless
    given). client: None (Dask's default scheduler over a dask.bag), a distributed.Client, or a
    scheduler's address. Returns {"mapped", "failed", "verdicts": {"pass", "warn", "fail"},
    "meshes": [{"input", "output", "status", "summary" or "error"}, ...]} in the order of the paths."""
    meshes = _meshes(paths)
    out_dir = _os.fsdecode(out_dir)
    _os.makedirs(out_dir, exist_ok=True)
    extension = "." + format.lower()
    if extension not in (".obj", ".ply", ".glb", ".gltf"):
        raise ValueError(f"map_many: format: '{format}' is not one of obj, ply, glb, gltf")
    options.setdefault("threads", 1)
    import uvtk

    uvtk.MapOptions.parse("")  # fail here, not in every task, when Dask is missing a piece below
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
            futures = client.map(_map_one, meshes, out_dir=out_dir, extension=extension, options=options, pure=False)
            records = client.gather(futures)
        finally:
            if own is not None:
                own.close()
    verdicts = {"pass": 0, "warn": 0, "fail": 0}
    for record in records:
        if record["status"] in verdicts:
            verdicts[record["status"]] += 1
    failed = sum(1 for r in records if r["status"] == "failed")
    return {"mapped": len(records) - failed, "failed": failed, "verdicts": verdicts, "meshes": list(records)}
