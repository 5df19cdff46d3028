"""The experiment as a figure: `experiment --plot` and python3 -m apprentice.plot."""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest

from conftest import BINARY, KITCHEN

SVG = "{http://www.w3.org/2000/svg}"


def texts_in(group):
    return [t.text or "" for t in group.iter(SVG + "text")]


def condition_groups(svg_path):
    root = ElementTree.parse(svg_path).getroot()  # raises on XML that is not well formed
    assert root.tag == SVG + "svg"
    return {g.get("id"): g for g in root.iter(SVG + "g") if (g.get("id") or "").startswith("condition-")}


def test_experiment_plot_writes_an_svg_with_one_group_per_condition(tmp_path):
    figure = tmp_path / "fig.svg"
    done = subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions",
                           "instruction,inst+search4", "--plot", str(figure)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "The figure is in " + str(figure) in done.stdout
    groups = condition_groups(figure)
    assert sorted(groups) == ["condition-inst-search4", "condition-instruction"]
    # Ours beside the paper's: instruction 48/636 against 76/757; inst+search4 40/603 both.
    instruction = texts_in(groups["condition-instruction"])
    assert "instruction" in instruction
    assert {"48", "636", "76", "757", "100"} <= set(instruction)
    search = texts_in(groups["condition-inst-search4"])
    assert search.count("40") == 2 and search.count("603") == 2


def test_the_module_draws_a_png_from_json_and_can_leave_out_the_paper(tmp_path):
    results = tmp_path / "results.json"
    results.write_text(json.dumps([{"condition": "instruction", "instructions": 48, "words": 636, "yes_no": 0,
                                    "completion_rate": 100.0}]))
    png = tmp_path / "fig.png"
    subprocess.run([sys.executable, "-m", "apprentice.plot", str(results), "-o", str(png)], check=True)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    svg = tmp_path / "alone.svg"
    subprocess.run([sys.executable, "-m", "apprentice.plot", str(results), "-o", str(svg), "--no-paper"], check=True)
    texts = texts_in(condition_groups(svg)["condition-instruction"])
    assert "636" in texts and "757" not in texts


def test_bad_results_are_refused_with_a_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"not": "results"}')
    done = subprocess.run([sys.executable, "-m", "apprentice.plot", str(bad), "-o", str(tmp_path / "x.svg")],
                          capture_output=True, text=True)
    assert done.returncode == 2
    assert "apprentice experiment --json" in done.stderr


def test_the_cli_refuses_another_extension(tmp_path):
    done = subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions", "instruction",
                           "--plot", str(tmp_path / "fig.pdf")], capture_output=True, text=True)
    assert done.returncode == 2
    assert "must be an .svg or .png file" in done.stderr


def test_without_matplotlib_the_cli_says_how_to_install_it(tmp_path):
    # A matplotlib that cannot be imported, ahead of Debian's on the path.
    fake = tmp_path / "no-matplotlib" / "matplotlib"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('matplotlib is not installed')\n")
    env = dict(os.environ, PYTHONPATH=str(fake.parent))
    done = subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions", "instruction",
                           "--plot", str(tmp_path / "fig.svg")], capture_output=True, text=True, env=env)
    assert done.returncode == 2
    assert "apt-get install" in done.stderr and "python3-matplotlib" in done.stderr
    assert not (tmp_path / "fig.svg").exists()


def test_without_python_the_cli_says_how_to_install_it(tmp_path):
    env = dict(os.environ, APPRENTICE_PYTHON=str(tmp_path / "no-python3"))
    done = subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions", "instruction",
                           "--plot", str(tmp_path / "fig.svg")], capture_output=True, text=True, env=env)
    assert done.returncode == 2
    assert "needs Python 3" in done.stderr and "apt-get install" in done.stderr
