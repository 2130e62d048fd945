"""The examples run (tiny frames) and write their plots."""
import os
import subprocess
import sys

import penumbra

EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples")


def run_example(name, tmp_path, *args):
    out = tmp_path / (name + ".png")
    subprocess.run([sys.executable, os.path.join(EXAMPLES, name + ".py"), "--out", str(out),
                    *args], check=True, capture_output=True, env=dict(os.environ, MPLBACKEND="Agg"))
    # A PNG the library reads back, of a plot's size: not an empty or truncated file.
    image = penumbra.read_image(str(out))
    assert image.shape[0] > 200 and image.shape[1] > 200
    assert image.std() > 0.01
    return out


def test_error_vs_time_plot(tmp_path):
    run_example("error_vs_time", tmp_path, "--size", "96x64", "--frames", "1",
                "--oracle-rays", "64")


def test_light_radius_sweep_plot(tmp_path):
    run_example("light_radius_sweep", tmp_path, "--size", "96x64", "--radii", "0,0.3,0.6",
                "--techniques", "exact,wedge-3pass")
