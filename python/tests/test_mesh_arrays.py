"""Scenes from dicts with numpy meshes: rendered like any scene, bad arrays refused by name."""
import numpy as np
import pytest

import penumbra
from conftest import HEIGHT, WIDTH


def tetrahedron(lift=1.0):
    vertices = np.array([[0, lift, 0], [1, lift, 0], [0, lift, 1], [0, lift + 1, 0]],
                        dtype=np.float64)
    triangles = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], dtype=np.int32)
    return vertices, triangles


def scene_dict(vertices, triangles, **mesh_keys):
    return {
        "camera": {"position": [3, 4, 5], "target": [0, 0.5, 0]},
        "lights": [{"center": [0.3, 6, 0.3], "radius": 0.3}],
        "meshes": [{"generator": "plane", "half_size": 4},
                   {"vertices": vertices, "triangles": triangles, "name": "tet", **mesh_keys}],
    }


def test_a_numpy_mesh_renders_and_casts_a_shadow():
    vertices, triangles = tetrahedron()
    scene = penumbra.load_scene(scene_dict(vertices, triangles))
    assert scene.meshes[1] == {"name": "tet", "triangles": 4, "vertices": 4, "closed": True}
    frame = penumbra.render(scene, technique="exact", width=WIDTH, height=HEIGHT, samples=64)
    visibility = frame.visibility[0]
    # The tetrahedron floats above the floor under the light: its shadow has an umbra and a
    # penumbra on the floor, and the rest of the floor is lit.
    assert visibility.min() == 0.0
    assert np.any((visibility > 0.0) & (visibility < 1.0))
    assert np.mean(visibility == 1.0) > 0.5


def test_array_meshes_take_the_file_entry_keys():
    vertices, triangles = tetrahedron(lift=0.0)
    moved = penumbra.load_scene(scene_dict(vertices, triangles,
                                           transform={"translate": np.array([0.0, 2.0, 0.0])}))
    low, high = moved.bounds
    assert high[1] == pytest.approx(3.0)


@pytest.mark.parametrize("change, message", [
    (lambda v, t: (v[:, :2], t), r"meshes\[1\]\.vertices: expected an array of shape \(N, 3\), got shape \(4, 2\)"),
    (lambda v, t: (v, t.reshape(-1)), r"meshes\[1\]\.triangles: expected an array of shape \(M, 3\)"),
    (lambda v, t: (v, t.astype(np.float32)), r"meshes\[1\]\.triangles: expected integer vertex indices"),
    (lambda v, t: (np.where(np.arange(12).reshape(4, 3) == 4, np.nan, v), t),
     r"meshes\[1\]: tet: vertex 1 has a non-finite coordinate \(1, nan, 0\)"),
    (lambda v, t: (v, np.where(t == 3, 7, t)), r"tet: triangle 1 \(corner 1\) uses vertex 7, out of range: there are 4 vertices"),
    (lambda v, t: (v, np.where(t == 3, -2, t)), r"tet: triangle 1 \(corner 1\) uses vertex -2, out of range"),
    (lambda v, t: (v * 1e39, t), r"tet: vertex 0 has a non-finite coordinate \(0, inf, 0\)"),
    (lambda v, t: (v[:0], t), r"tet: the mesh has no vertices"),
])
def test_bad_arrays_raise_with_a_message(change, message):
    vertices, triangles = change(*tetrahedron())
    with pytest.raises(penumbra.Error, match=message):
        penumbra.load_scene(scene_dict(vertices, triangles))


def test_a_mesh_needs_both_arrays():
    vertices, _ = tetrahedron()
    scene = scene_dict(vertices, None)
    del scene["meshes"][1]["triangles"]
    with pytest.raises(penumbra.Error, match="needs both"):
        penumbra.load_scene(scene)
