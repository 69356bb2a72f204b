# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""tests/docs/keywords.py, the guide's keyword coverage (docs.keywords):
records read as written by checkedInput::recordKeywords, keywords counted
as documented only in inline code of the prose, the undocumented ones
named; hand-written records and pages."""
import importlib.util
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location(
    "keywords", ROOT / "tests" / "docs" / "keywords.py")
keywords = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(keywords)


def write(path, text):
    path.write_text(text)
    return path


def test_records_merge_roles_across_files(tmp_path):
    write(tmp_path / "case.a.txt", "seed\texactBrownianMotion\nE\tparticle\n")
    write(tmp_path / "case.b.txt", "seed\tresuspension of floor\n")
    assert keywords.recorded(tmp_path) == {
        "seed": {"exactBrownianMotion", "resuspension of floor"},
        "E": {"particle"},
    }


def test_only_inline_code_of_prose_documents(tmp_path):
    guide = tmp_path / "guide"
    guide.mkdir()
    write(guide / "a.md", "Give `meanFreePath 66.5e-9;` or `p`.\n"
                          "```\nslipCoefficients Davies;\n```\n"
                          "The word maxDiameter without backticks.\n"
                          "- a list:\n  ```\n  `seed 1;`\n  ```\n")
    words = keywords.documented(guide)
    assert {"meanFreePath", "p"} <= words
    assert "slipCoefficients" not in words
    assert "maxDiameter" not in words
    # an exponent is no keyword; an indented fence is a fence
    assert "e" not in words
    assert "seed" not in words


def test_undocumented_named_and_exit_codes(tmp_path, capsys, monkeypatch):
    records = tmp_path / "records"
    records.mkdir()
    guide = tmp_path / "guide"
    guide.mkdir()
    write(guide / "a.md", "`seed`\n")
    monkeypatch.delenv("CI", raising=False)
    assert keywords.main(["keywords.py", str(records), str(guide)]) == 77
    monkeypatch.setenv("CI", "true")
    assert keywords.main(["keywords.py", str(records), str(guide)]) == 1
    write(records / "case.a.txt", "seed\tx\nT\texactBrownianMotion\n")
    assert keywords.main(["keywords.py", str(records), str(guide)]) == 1
    assert "not in the guide: T (of exactBrownianMotion)" in capsys.readouterr().out
    write(guide / "b.md", "`T 293.15;`\n")
    assert keywords.main(["keywords.py", str(records), str(guide)]) == 0
