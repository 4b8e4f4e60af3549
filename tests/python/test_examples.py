"""The README's Python example and examples/sweep.py run as written."""
import os
import re
import subprocess
import sys


def readme_python_blocks(source_dir):
    with open(os.path.join(source_dir, "README.md")) as f:
        text = f.read()
    section = text[text.index("## From Python"):]
    section = section[: section.index("\n## ", 1)]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def test_readme_example_runs(source_dir, capsys):
    blocks = readme_python_blocks(source_dir)
    assert blocks, "no Python example in the README's From Python section"
    for block in blocks:
        exec(compile(block, "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert "Equilibrium(a=" in out and "Fraction(-2, 1)" in out


def test_sweep_example_writes_its_png(source_dir, tmp_path):
    png = tmp_path / "sweep.png"
    result = subprocess.run([sys.executable, os.path.join(source_dir, "examples", "sweep.py"), "--out", str(png)],
                            cwd=tmp_path, capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"})
    assert result.returncode == 0, result.stderr
    with open(png, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert png.stat().st_size > 20000
