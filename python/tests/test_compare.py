"""penumbra.compare: the CLI's metrics on arrays and files."""
import subprocess

import numpy as np
import pytest

import penumbra
from conftest import HEIGHT, WIDTH


def test_metrics_of_known_differences():
    a = np.zeros((4, 5), np.float32)
    b = a.copy()
    b[1, 2] = 0.5
    b[3, 4] = 0.005
    d = penumbra.compare(a, b, tolerance=0.01)
    assert d["pixels"] == 20
    assert d["mae"] == pytest.approx(0.505 / 20)
    assert d["max_error"] == pytest.approx(0.5)
    assert d["count_over_tolerance"] == 1
    mask = np.ones((4, 5), np.float32)
    mask[1, 2] = 0.0  # a background pixel of a depth buffer: not compared
    d = penumbra.compare(a, b, mask=mask)
    assert d["pixels"] == 19 and d["count_over_tolerance"] == 0
    b[0, 0] = np.nan
    assert penumbra.compare(a, b)["count_nonfinite"] == 1


def test_same_figures_as_the_cli(cli, tmp_path):
    files = {}
    for technique in ("wedge-3pass", "exact"):
        files[technique] = tmp_path / f"{technique}.exr"
        subprocess.run([cli, "render", "spheres", "--technique", technique, "--width", str(WIDTH),
                        "--height", str(HEIGHT), "--visibility", str(files[technique]),
                        "--depth", str(tmp_path / "depth.exr"),
                        "-o", str(tmp_path / "c.png"), "--quiet"], check=True)
    out = subprocess.run([cli, "compare", str(files["wedge-3pass"]), str(files["exact"]),
                          "--mask", str(tmp_path / "depth.exr")],
                         capture_output=True, text=True).stdout
    d = penumbra.compare(files["wedge-3pass"], files["exact"], mask=tmp_path / "depth.exr")
    # The CLI prints its figures to 6 significant digits.
    assert f"MAE {d['mae']:.6g}  RMSE {d['rmse']:.6g}  max {d['max_error']:.6g}" in out, out
    assert d["pixels"] < WIDTH * HEIGHT and d["mae"] > 0


def test_size_mismatch_raises():
    with pytest.raises(penumbra.Error, match="size"):
        penumbra.compare(np.zeros((2, 2)), np.zeros((3, 2)))
