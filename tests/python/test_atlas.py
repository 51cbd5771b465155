"""The atlas through Python: every keyword reaches the engine typed, the verdict passes on a knot,
and the layout keeps the margin (recounted here from the UVs, apart from the engine)."""
import numpy as np
import pytest

import uvtk


def knot():
    from pathlib import Path
    here = Path(__file__).resolve().parents[2]
    return uvtk.read_mesh(str(here / "meshes" / "torus_knot.glb"))


def test_atlas_passes_and_keeps_its_margin_on_a_knot():
    m = uvtk.map(knot(), projector="atlas", margin=8, texture_size=(2048, 1024))
    assert m.verdict["status"] == "pass"
    a = m.summary["atlas"]
    assert a["charts"] > 1 and a["gutter_texels"] >= 8 - 1e-6 and a["border_texels"] >= 8 - 1e-6
    uv = m.uv * np.array([2048.0, 1024.0])
    assert uv.min() >= 8 - 1e-6 and uv[..., 0].max() <= 2048 - 8 + 1e-6 and uv[..., 1].max() <= 1024 - 8 + 1e-6
    e1, e2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    assert (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] > 0).all()  # no face mirrored


def test_atlas_keywords_are_typed_and_refused_elsewhere():
    with pytest.raises(TypeError, match="angle_limit"):
        uvtk.map(knot(), projector="atlas", angle_limit="wide")
    with pytest.raises(ValueError, match="margin"):
        uvtk.map(knot(), projector="sphere", margin=4)
    with pytest.raises(ValueError, match="angle_limit"):
        uvtk.map(knot(), projector="atlas", angle_limit=95)


def test_lscm_and_arap_are_mappings_like_any_other():
    for projector in ("lscm", "arap"):
        m = uvtk.map(knot(), projector=projector)
        assert m.verdict["status"] in ("pass", "warn"), m.verdict
        assert m.summary["atlas"]["charts"] >= 1
