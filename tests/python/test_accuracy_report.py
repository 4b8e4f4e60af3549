"""scripts/accuracy_report.py: docs/accuracy.md's tables are rewritten from accuracy_test's
output on every path, name their run, and a failing test writes nothing."""
import os
import stat
import subprocess
import sys

OUTPUT = """array kernels: {isa}
pressure, exact: 1200 points, max 4.078 eps, mean 0.8218 eps, worst at m = 100, a/b1 = 0.49, x/a = 0.999, b1 = 3.7
pressure, exact, array API: 3600 points, max {array_max} eps, mean 0.8857 eps, worst at m = 0.2, a/b1 = 0.49, x/a = 0.999, b1 = 3.7
pressure, printed, array API: 3600 points, max 4.227 eps, mean 0.881 eps, worst at m = 0.001, a/b1 = 0.5, x/a = 0.1, b1 = 3.7
pressure (array), a > b1/2, |x| < b1/2: 2261 points, max 40.46 eps, mean 0.9879 eps, worst at m = 1e+04, a/b1 = 0.9999, x/a = 0.5001, b1 = 10
pressure (array), a > b1/2, |x| > b1/2: 1278 points, max 21 eps, mean 0.9002 eps, worst at m = 1e+04, a/b1 = 0.9, x/a = 0.5556, b1 = 3.7
n = 256: roughness pressure max error 1.91296e-13 (array API 1.91075e-13) x E*H2 n pi/b1; naive eq. 18 sum max error 5.96007e+174 (|s(v)| <= 1/n)
"""


def fake_build(tmp_path, exit_status=0):
    """A build tree whose accuracy_test prints OUTPUT for the path WAVECONTACT_ISA asks."""
    test = tmp_path / "build" / "tests" / "accuracy_test"
    test.parent.mkdir(parents=True)
    lines = {isa: OUTPUT.format(isa=isa, array_max=m) for isa, m in (("scalar", "4.078"), ("avx2", "3.644"),
                                                                        ("avx512", "3.644"))}
    test.write_text("#!/bin/sh\ncase \"${WAVECONTACT_ISA:-avx512}\" in\n" +
                    "".join(f"  {isa}) cat <<'END'\n{text}END\n;;\n" for isa, text in lines.items()) +
                    f"esac\nexit {exit_status}\n")
    test.chmod(test.stat().st_mode | stat.S_IEXEC)
    return tmp_path / "build"


def run(source_dir, build, docs):
    script = os.path.join(source_dir, "scripts", "accuracy_report.py")
    return subprocess.run([sys.executable, script, "--build", str(build), "--docs", str(docs)], capture_output=True,
                          text=True)


def test_tables_are_written_from_every_path(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    page = docs / "accuracy.md"
    page.write_text("<!-- accuracy:array-paths -->\nold\n<!-- /accuracy:array-paths -->\n"
                    "<!-- accuracy:roughness -->\nold\n<!-- /accuracy:roughness -->\n")
    r = run(source_dir, fake_build(tmp_path), docs)
    assert r.returncode == 0, r.stderr
    text = page.read_text()
    assert "old" not in text
    assert "best path avx512" in text
    assert "| array API | scalar | avx2 | avx512 |" in text
    assert "| pressure, exact: max / mean | 4.08 ε / 0.886 ε | 3.64 ε / 0.886 ε | 3.64 ε / 0.886 ε |" in text
    assert "| pressure beyond b1/2, \\|x\\| < b1/2: max | 40.5 ε | 40.5 ε | 40.5 ε |" in text
    assert "| 256 | 1.9·10⁻¹³ | 1.9·10⁻¹³ | 6·10¹⁷⁴ |" in text


def test_a_failing_test_writes_nothing(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    original = "<!-- accuracy:roughness -->\nkept\n<!-- /accuracy:roughness -->\n"
    (docs / "accuracy.md").write_text(original)
    r = run(source_dir, fake_build(tmp_path, exit_status=1), docs)
    assert r.returncode != 0
    assert "failed" in r.stderr
    assert (docs / "accuracy.md").read_text() == original
