# voxc.check: diagnostics as objects, nothing raised for the file's own errors.
import voxc
from conftest import EXAMPLES

BROKEN = """world { size = [16, 16, 16]; }
field ground = clamp(8 - y, 0, 1) + undefined_thing;
"""


def test_broken_text_gives_located_errors():
    diagnostics = voxc.check(text=BROKEN, name="broken.vox")
    errors = [d for d in diagnostics if d.severity == "error"]
    assert errors, diagnostics
    first = errors[0]
    assert first.code.startswith("E0")
    assert first.file == "broken.vox"
    assert first.line == 2
    assert first.column == BROKEN.splitlines()[1].index("undefined_thing") + 1
    assert "undefined_thing" in first.message
    assert first.rendered.startswith(f"broken.vox:2:{first.column}: error {first.code}: ")
    assert str(first) == first.rendered


def test_broken_file(tmp):
    path = tmp / "broken.vox"
    path.write_text(BROKEN)
    diagnostics = voxc.check(path)  # a PathLike
    assert [(d.file, d.line) for d in diagnostics if d.severity == "error"][0] == (str(path), 2)
    assert [d.code for d in voxc.check(str(path))] == [d.code for d in diagnostics]  # a str ending in .vox


def test_missing_file_is_a_diagnostic(tmp):
    diagnostics = voxc.check(str(tmp / "nowhere.vox"))
    assert [(d.code, d.severity, d.line) for d in diagnostics] == [("E0100", "error", 0)]


def test_clean_example_has_no_errors():
    assert [d for d in voxc.check(EXAMPLES / "scene.vox") if d.severity == "error"] == []


def test_override_of_an_undeclared_const_is_reported():
    diagnostics = voxc.check(EXAMPLES / "scene.vox", overrides={"NO_SUCH_CONST": 1.0})
    assert any(d.code == "E0002" and "NO_SUCH_CONST" in d.message for d in diagnostics)


def test_program_of_a_broken_file_raises_user_error_with_locations():
    try:
        voxc.Program(text=BROKEN, name="broken.vox")
    except voxc.UserError as error:
        assert "broken.vox:2:" in str(error)
    else:
        raise AssertionError("Program accepted a file with errors")
