"""Penumbra: soft and hard shadow techniques, a ray-traced oracle, and their measurements.

    import penumbra
    scene = penumbra.load_scene("spheres")
    frame = penumbra.render(scene, technique="exact", width=320, height=214, samples=64)
    frame.color            # H x W x 3 float32, linear RGB
    frame.visibility[0]    # H x W float32 per light
    penumbra.techniques()  # every technique, its traits and options

Errors from the library (bad scenes, arrays, options, files) raise penumbra.Error, a
ValueError, with the library's message.
"""
import json
import os

import numpy as np

from ._penumbra import (Camera, Error, Frame, Light, LightList, Scene, builtin_scenes,
                        read_exr, read_image, techniques)
from . import _penumbra

__all__ = ["Camera", "Error", "Frame", "Light", "LightList", "Renderer", "Scene",
           "builtin_scenes", "compare", "load_scene", "read_exr", "read_image", "render",
           "techniques"]


def load_scene(source, up="y"):
    """Loads a scene.

    source: a built-in scene's name (penumbra.builtin_scenes()), a scene file (.json) or a mesh
    file's path (OBJ, PLY, glTF, ...; `up` is its up axis: "x", "y" or "z"), or a dict in the
    scene-file format (docs/scene-format.md) in which a mesh entry may also be
    {"vertices": array N x 3, "triangles": array M x 3} (numpy or nested lists; triangles
    counter-clockwise seen from the front) with the keys a file entry has ("name", "material",
    "transform", "fit"). Arrays get the file loader's checks and welding; a wrong shape, a
    non-finite vertex or an index out of range raises penumbra.Error naming the mesh. A dict's
    relative mesh file paths are relative to the current directory.
    """
    if isinstance(source, dict):
        return _scene_from_dict(source)
    if isinstance(source, (str, os.PathLike)):
        return _penumbra._load_scene(os.fspath(source), up)
    raise TypeError(f"load_scene takes a scene name, a path or a dict, not {type(source).__name__}")


def _mesh_array(value, path, key, integer):
    array = np.asarray(value)
    if array.ndim != 2 or array.shape[1] != 3:
        raise Error(f"<dict>: {path}.{key}: expected an array of shape ({'M' if integer else 'N'}, 3), "
                    f"got shape {array.shape}")
    if integer and not np.issubdtype(array.dtype, np.integer):
        raise Error(f"<dict>: {path}.{key}: expected integer vertex indices, got {array.dtype}")
    if not integer and not (np.issubdtype(array.dtype, np.floating)
                            or np.issubdtype(array.dtype, np.integer)):
        raise Error(f"<dict>: {path}.{key}: expected real coordinates, got {array.dtype}")
    # A float64 coordinate beyond float32's range becomes inf here; the library's check then
    # names the vertex, so numpy's overflow warning would only repeat it.
    with np.errstate(over="ignore"):
        return np.ascontiguousarray(array, dtype=np.int64 if integer else np.float32)


def _json_value(value):
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not a scene-file value")


def _scene_from_dict(scene):
    meshes = []
    arrays = []
    for i, entry in enumerate(scene.get("meshes", [])):
        if isinstance(entry, dict) and ("vertices" in entry or "triangles" in entry):
            path = f"meshes[{i}]"
            for key in ("vertices", "triangles"):
                if key not in entry:
                    raise Error(f"<dict>: {path}: a mesh given as arrays needs both \"vertices\" "
                                f"and \"triangles\"")
            vertices = _mesh_array(entry["vertices"], path, "vertices", integer=False)
            triangles = _mesh_array(entry["triangles"], path, "triangles", integer=True)
            rest = {k: v for k, v in entry.items() if k not in ("vertices", "triangles")}
            meshes.append({**rest, "arrays": len(arrays)})
            arrays.append((vertices, triangles))
        else:
            meshes.append(entry)
    document = dict(scene)
    if "meshes" in scene:
        document["meshes"] = meshes
    text = json.dumps(document, default=_json_value)
    return _penumbra._parse_scene_json(text, "<dict>", os.getcwd(), arrays)


def _option_text(value):
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _option_texts(options):
    return {name: _option_text(value) for name, value in options.items()}


def render(scene, technique="exact", width=None, height=None, threads=0, simd=True,
           occlusion_culling="auto", caster_culling="auto", delay_stream=0, **options):
    """Renders one frame of `scene` (a Scene, or anything load_scene takes).

    technique: a name from penumbra.techniques(); its options are keywords (tile_size=8,
    cull="zmax", smooth=True), listed below. width, height: the frame's size (None: the
    scene's). threads: worker threads (0: all cores). simd=False runs every kernel's scalar
    twin (identical images). occlusion_culling and caster_culling ("auto", "on", "off"),
    delay_stream (bytes, 0: none): the eye pass's object culling, the shadow stages' caster
    culling and the eye pass's delay stream, as `penumbra render` has them; none changes the
    images, only the work and counters. Returns a Frame: .color (H x W x 3 float32), .visibility (one
    H x W float32 per light), .depth, .counters, .times (pass -> ms, with 'prepare'); the arrays
    are views of the frame's buffers, not copies. The GIL is released while rendering.
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    return _penumbra._render(scene, technique, width or 0, height or 0, threads, simd,
                             occlusion_culling, caster_culling, delay_stream,
                             _option_texts(options))


class Renderer:
    """A technique prepared once for a scene, rendering frame after frame.

        renderer = penumbra.Renderer(scene, technique="wedge-3pass", width=640, height=427)
        for x in range(10):
            scene.lights[0].center = (x, 5, 0)   # lights and camera may change between frames
            frame = renderer.render()

    What may change between frames: scene.camera (position, target, up, fov, near) and
    scene.lights (centre, radius, colour, intensity, shape; lights added or removed); they are
    checked at each render. The geometry may not (the technique's prepared state, such as the
    oracle's BVH, is built from it; Python offers no way to change it). Options and frame size
    are fixed at construction (see render for them). A frame's arrays are views of a buffer the
    renderer reuses once Python holds no array of that frame; a frame held stays unchanged.
    render() releases the GIL; one renderer renders one frame at a time, two renderers in two
    threads render at once (each on its own scene, or on one scene nobody changes meanwhile).
    """

    def __init__(self, scene, technique="exact", width=None, height=None, threads=0, simd=True,
                 occlusion_culling="auto", caster_culling="auto", delay_stream=0, **options):
        if not isinstance(scene, Scene):
            scene = load_scene(scene)
        self._renderer = _penumbra._Renderer(scene, technique, width or 0, height or 0, threads,
                                             simd, occlusion_culling, caster_culling,
                                             delay_stream, _option_texts(options))

    def render(self):
        """Renders a frame with the scene's current camera and lights; returns a Frame."""
        return self._renderer.render()

    @property
    def scene(self):
        """The scene (its camera and lights are what the next frame uses)."""
        return self._renderer.scene

    @property
    def prepare_ms(self):
        """Milliseconds it took to prepare the technique for the scene."""
        return self._renderer.prepare_ms

    @property
    def technique(self):
        """The technique and its options, described."""
        return self._renderer.technique


def compare(a, b, mask=None, tolerance=0.01):
    """Differences between two images, as `penumbra compare` reports them.

    a, b: H x W arrays (visibility) or H x W x 3 (linear RGB), or EXR / PNG paths. mask: an
    H x W array or a depth EXR's path; pixels where it is > 0 are compared (a depth buffer's
    covered pixels). Returns a dict: pixels, mae, rmse, max_error, count_over_tolerance,
    fraction_over_tolerance (error > tolerance, non-finite pixels included), count_nonfinite.
    Per-pixel error is |a - b|, for colour the largest channel's.
    """
    def image(value):
        if isinstance(value, (str, os.PathLike)):
            return read_image(os.fspath(value))
        return np.asarray(value, dtype=np.float32)
    return _penumbra._compare(image(a), image(b), None if mask is None else image(mask),
                              float(tolerance))


def _options_help():
    lines = ["", "Techniques and their options (keyword: kind, default):"]
    for info in techniques():
        kind = "soft" if info["traits"]["soft"] else "hard"
        lines.append(f"  {info['name']} ({kind}): {info['summary']}")
        for option in info["options"]:
            detail = option["kind"]
            if "range" in option:
                detail += f" {option['range'][0]}..{option['range'][1]}"
            if "choices" in option:
                detail += " " + "|".join(option["choices"])
            lines.append(f"      {option['keyword']}: {detail}, default {option['default']!r}"
                         f" -- {option['help']}")
    return "\n".join(lines)


render.__doc__ += _options_help()
Renderer.__init__.__doc__ = "See Renderer and render for the arguments." + _options_help()
