"""penumbra.render and the technique table against the CLI and the library's own claims."""
import subprocess

import numpy as np
import pytest

import penumbra
from conftest import HEIGHT, WIDTH


def test_visibility_equals_the_cli_exr_bit_for_bit(cli, tmp_path):
    # The module must render what the CLI renders: same scene, technique, options and size give
    # the same float bits. A difference means the bindings build other options or another frame.
    exr = tmp_path / "exact.exr"
    subprocess.run([cli, "render", "spheres", "--technique", "exact", "--samples", "64",
                    "--width", str(WIDTH), "--height", str(HEIGHT), "--visibility", str(exr),
                    "-o", str(tmp_path / "exact.png"), "--quiet"], check=True)
    frame = penumbra.render("spheres", technique="exact", width=WIDTH, height=HEIGHT, samples=64)
    from_cli = penumbra.read_exr(str(exr))
    assert from_cli.shape == (HEIGHT, WIDTH)
    differing = np.argwhere(frame.visibility[0].view(np.uint32) != from_cli.view(np.uint32))
    assert len(differing) == 0, (
        f"{len(differing)} pixels differ, first at (row, column) {differing[0].tolist()}: "
        f"{frame.visibility[0][tuple(differing[0])]!r} here, {from_cli[tuple(differing[0])]!r} "
        f"from the CLI")
    # And the frame has umbra and penumbra, so equality is not two empty images.
    visibility = frame.visibility[0]
    assert visibility.min() == 0.0 and np.any((visibility > 0.0) & (visibility < 1.0))


def test_frame_arrays_are_typed_views_of_the_frame():
    scene = penumbra.load_scene("multilight")
    frame = penumbra.render(scene, technique="volume", width=WIDTH, height=HEIGHT)
    assert frame.color.shape == (HEIGHT, WIDTH, 3) and frame.color.dtype == np.float32
    assert len(frame.visibility) == len(scene.lights) > 1
    for visibility in frame.visibility:
        assert visibility.shape == (HEIGHT, WIDTH) and visibility.dtype == np.float32
    assert frame.depth.shape == (HEIGHT, WIDTH)
    # Views, not copies: numpy does not own the memory; the frame's capsule does.
    assert not frame.color.flags.owndata and frame.color.base is not None
    assert not frame.visibility[0].flags.owndata
    # A hard technique on a lit scene: some pixels shadowed, some lit, the background at 0 depth.
    assert set(np.unique(frame.visibility[0])) <= {0.0, 1.0}
    assert frame.counters["silhouette_edges"] > 0 and frame.counters["stencil_writes"] > 0
    assert "prepare" in frame.times and frame.frame_ms > 0
    assert frame.depth.min() == 0.0 and frame.depth.max() > 0.0


def test_arrays_outlive_the_frame_object():
    # The capsule keeps the buffers alive: an array kept after the Frame is gone must still hold
    # the image (a dangling pointer would read freed memory).
    color = penumbra.render("spheres", technique="volume", width=WIDTH, height=HEIGHT).color
    expected = penumbra.render("spheres", technique="volume", width=WIDTH, height=HEIGHT).color
    assert np.array_equal(color, expected)


def test_techniques_list_traits_and_options():
    table = {t["name"]: t for t in penumbra.techniques()}
    assert {"exact", "volume", "wedge-3pass", "reference"} <= set(table)
    assert table["exact"]["traits"]["soft"] and table["exact"]["traits"]["exact"]
    samples = {o["keyword"]: o for o in table["exact"]["options"]}["samples"]
    assert samples["kind"] == "integer" and samples["default"] == 256
    assert samples["range"] == (1, 4096)
    cull = {o["keyword"]: o for o in table["wedge-3pass"]["options"]}["cull"]
    assert cull["choices"] == ["none", "zmax", "full"]


def test_help_lists_the_options():
    doc = penumbra.render.__doc__
    assert "tile_size" in doc and "wedge-3pass" in doc and "samples" in doc


def test_option_keywords_reach_the_technique():
    # tile_size given as a keyword must change the work counted: otherwise it was dropped.
    coarse = penumbra.render("columns", technique="wedge-3pass", width=WIDTH, height=HEIGHT,
                             tile_size=64, cull="zmax")
    fine = penumbra.render("columns", technique="wedge-3pass", width=WIDTH, height=HEIGHT,
                           tile_size=4, cull="zmax")
    assert coarse.counters["tiles_tested"] != fine.counters["tiles_tested"]
    smooth = penumbra.render("spheres", technique="wedge-3pass", width=WIDTH, height=HEIGHT,
                             smooth=True)
    plain = penumbra.render("spheres", technique="wedge-3pass", width=WIDTH, height=HEIGHT)
    assert not np.array_equal(smooth.visibility[0], plain.visibility[0])


@pytest.mark.parametrize("call, message", [
    (lambda: penumbra.render("spheres", technique="nope"), "nope"),
    (lambda: penumbra.render("spheres", technique="exact", samples=0), "--samples"),
    (lambda: penumbra.render("spheres", technique="volume", samples=4), "samples"),
    (lambda: penumbra.render("spheres", technique="volume", width=99999, height=10), "99999"),
    (lambda: penumbra.load_scene("no-such-scene.json"), "no-such-scene.json"),
    (lambda: penumbra.render("spheres", technique="volume", delay_stream=-1), "delay_stream"),
    (lambda: penumbra.render("spheres", technique="volume", caster_culling="yes"), "yes"),
])
def test_errors_raise_with_the_library_message(call, message):
    with pytest.raises(penumbra.Error, match=message):
        call()


def test_culling_switches_change_the_work_not_the_image():
    # The eye pass's occlusion culling, the shadow stages' caster culling and the delay stream
    # must leave every float bit of the frame as it is: a difference means the switches do not
    # reach the library as the CLI's flags do, or a culling is not conservative. The counters
    # show each switch reached it.
    scene = penumbra.load_scene("interior:1")
    plain = penumbra.render(scene, technique="volume", width=WIDTH, height=HEIGHT,
                            occlusion_culling="off", caster_culling="off")
    culled = penumbra.render(scene, technique="volume", width=WIDTH, height=HEIGHT,
                             occlusion_culling="on", caster_culling="on", delay_stream=1 << 20)
    for a, b in zip(plain.visibility + [plain.color, plain.depth],
                    culled.visibility + [culled.color, culled.depth]):
        assert np.array_equal(a.view(np.uint32), b.view(np.uint32))
    assert plain.counters.get("occlusion_scene_triangles", 0) == 0
    assert culled.counters["occlusion_scene_triangles"] > 0
    assert culled.counters["casters_tested"] > 0 and plain.counters.get("casters_tested", 0) == 0
    assert culled.counters["delay_ring_triangles"] > 0
