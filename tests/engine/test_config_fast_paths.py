"""The configuration's fast paths answer as the slow ones: ``*.suffix`` patterns (the default
``include``) without pathspec, and folders resolved once per command (:func:`one_resolution`)."""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

import pathspec
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.engine.config import Config, ConfigFinder, _resolved, _suffixes, one_resolution
from zero.engine.config_file import patterns
from zero.engine.discovery import holds_lists
from zero.engine.results import LintOptions
from zero.files import path_str
from zero.forms import DEFAULT_INCLUDE, _suffix, is_project, is_xml_name, xml_form

_PARTS = st.lists(st.sampled_from(["a", ".lis", "x.lis", ".nc", "nc", "*", "[", "\\", " ", "ü", ".", "..", "",
                                   ".XML", ".xml", "lis", "#", "!"]), max_size=6)


_ROOT = "/zero-fast-path-root"  # a configuration's folder that does not exist: nothing in it is a link


@given(st.lists(_PARTS, max_size=4))
@example([["."], [], [".lis"]])  # `.//.lis`: pathspec reads `/.lis` (one `./` stripped), no; zero names it `.lis`
@example([["x.lis"], ["a"]])  # a folder's suffix matches what is below it
@settings(max_examples=400)
def test_suffix_patterns_match_as_pathspec(parts: list[list[str]]) -> None:
    """Every name zero matches a file by (``Config.relative`` of a path as ``collect_files`` gives it:
    its folder resolved, so no empty, ``.`` or ``..`` folder and no leading ``./``; else the file's own name)
    is matched by the ``*.suffix`` fast path as pathspec matches it. A text such as ``.//.lis`` never
    reaches the matcher (pathspec and the fast path differ on it)."""
    file = path_str(_ROOT + "/" + "/".join("".join(p) for p in parts))
    cfg = Config(path=_ROOT + "/zero.toml")
    rel = cfg.relative(file)
    name = rel if rel is not None else os.path.basename(file)
    assert "//" not in name and not name.startswith(("./", "/")) and "\n" not in name  # the fast path's domain
    suffixes = _suffixes(cfg.include)
    assert suffixes is not None
    spec = pathspec.GitIgnoreSpec.from_lines(list(DEFAULT_INCLUDE))
    assert cfg.included(file) == spec.match_file(name)
    assert any(part.endswith(suffixes) for part in name.split("/")) == spec.match_file(name)


@pytest.mark.parametrize("globs", [("*.lis", "old/"), ("*.li?",), ("*.[lL]is",), ("**/*.lis",), ("*",), ("*lis",),
                                   ("!*.lis",), ("*.lis ",)])
def test_other_patterns_go_to_pathspec(globs: tuple[str, ...]) -> None:
    assert _suffixes(globs) is None


def test_default_include_is_a_suffix_pattern() -> None:
    assert _suffixes(DEFAULT_INCLUDE) == tuple(g[1:] for g in DEFAULT_INCLUDE)


def test_matching_is_the_same_inside_and_outside_one_resolution(tmp_path: Path, monkeypatch: pytest.MonkeyPatch
                                                                 ) -> None:
    (tmp_path / "proj" / "sub.lis").mkdir(parents=True)
    (tmp_path / "proj" / "real").mkdir()
    (tmp_path / "proj" / "link").symlink_to(tmp_path / "proj" / "real")
    (tmp_path / "elsewhere").mkdir()
    cfg_file = tmp_path / "proj" / "zero.toml"
    cfg_file.write_text("")
    monkeypatch.chdir(tmp_path / "proj")
    files = [Path("a.lis"), Path("sub.lis/x.txt"), Path("link/m.lis"), Path("real/m.nc"), Path("real/m.txt"),
             tmp_path / "elsewhere" / "o.lis", tmp_path / "elsewhere" / "o.txt", Path("../elsewhere/o.xml"),
             Path(str(tmp_path / "proj") + "//real/./m.lis")]
    for cfg in (Config(path=str(cfg_file)), Config()):
        expected = []
        for f in files:
            try:
                rel: str | None = _resolved(f).relative_to(cfg.root.resolve()).as_posix()
            except ValueError:
                rel = None
            expected.append((rel, patterns(DEFAULT_INCLUDE).match_file(rel if rel is not None else f.name)))
        assert [(cfg.relative(f), cfg.included(f)) for f in files] == expected
        with one_resolution():
            assert [(cfg.relative(f), cfg.included(f)) for f in files] == expected
            assert [(cfg.relative(f), cfg.included(f)) for f in files] == expected


def test_one_resolution_ends_with_its_block(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A link changed after a command is seen by the next (the language server lives long)."""
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "zero.toml").write_text("")
    link = tmp_path / "l"
    link.symlink_to(tmp_path / "a")
    cfg = Config(path=str(tmp_path / "b" / "zero.toml"))
    with one_resolution():
        assert cfg.relative(link / "m.lis") is None
    link.unlink()
    link.symlink_to(tmp_path / "b")
    assert cfg.relative(link / "m.lis") == "m.lis"
    with one_resolution():
        assert cfg.relative(link / "m.lis") == "m.lis"
    assert os.path.islink(link)



def test_the_toml_guard_is_asked_where_a_key_could_be_too_long(tmp_path: Path) -> None:
    """parse_config asks guard_toml only of a text of MAX_NESTING dots or more (a key of more than
    MAX_NESTING parts, which it refuses, holds as many): a usual configuration loads no zero.structured.toml."""
    from zero.engine.config import _GUARDED_DOTS, parse_config
    from zero.errors import ZeroError
    from zero.structured.common import MAX_NESTING
    from zero.structured.toml import guard_toml

    assert _GUARDED_DOTS == MAX_NESTING
    cfg = tmp_path / "zero.toml"
    cfg.write_text("x." + ".".join(["k"] * 64) + " = 1\n", encoding="utf-8")  # 65 parts, 64 dots
    with pytest.raises(ZeroError, match="more than 64 dotted parts"):
        parse_config(cfg)
    most = ".".join(["k"] * 64) + " = 1\n"  # 64 parts, 63 dots: read, as guard_toml reads it
    assert most.count(".") == _GUARDED_DOTS - 1
    guard_toml(most)
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text('[tool.zero]\nselect = ["R"]\n\n[tool.other]\n' + most, encoding="utf-8")
    assert parse_config(pyproject) is not None


_SPELLINGS = st.lists(st.sampled_from(["a", "b", "sub", ".", "..", "", "x.lis"]), min_size=1, max_size=5)


def _tree(root: Path) -> None:
    """Configurations at three depths, and a folder without one."""
    for folder in ("", "a", "a/b", "sub"):
        (root / folder).mkdir(parents=True, exist_ok=True)
    for folder in ("", "a/b"):
        (root / folder / "zero.toml").write_text('select = ["R"]\n', encoding="utf-8")


def _reference_relative(cfg: Config, file: str) -> str | None:
    """``Config.relative`` as written before its fast path: ``os.path.split`` of the file's text."""
    parent, name = os.path.split(file)
    folder = os.path.realpath(parent or ".")
    own = os.fspath(cfg.path) if cfg.path is not None else None
    root = os.path.realpath((os.path.dirname(own) or ".") if own is not None else os.getcwd())
    head = root if root.endswith("/") else root + "/"
    rel = "" if folder == root else folder[len(head):] if folder.startswith(head) else "\0"
    if not rel:
        return name if name else "."
    return None if rel == "\0" else rel + "/" + name if name else rel


@pytest.mark.skipif(os.altsep is not None, reason="the fast paths are POSIX's (one separator)")
@given(st.lists(st.tuples(_SPELLINGS, st.sampled_from(["relative", "below the tree", "from /"])), min_size=1,
                max_size=4))
@example([(["x.lis"], "relative"), (["x.lis"], "from /")])  # `x.lis` here, then `/x.lis`: two folders
@example([(["a", "", "b", "x.lis"], "relative"), (["a", "b", "x.lis"], "below the tree")])  # `a//b/x.lis`
@settings(max_examples=300, deadline=None)
def test_a_files_configuration_and_place_are_its_folders(tmp_path_factory: pytest.TempPathFactory,
                                                         names: list[tuple[list[str], str]]) -> None:
    """``ConfigFinder.for_path`` of a file answers per folder as the name writes it (its text to the last
    separator) and ``Config.relative`` splits by that text: both as ``os.path.dirname``/``os.path.split``
    would have them, for any spelling of a name (doubled, ``.`` and ``..`` parts, relative, absolute, at the
    file system's root), one finder asked for several names in turn, each twice, inside one resolution or
    not."""
    root = tmp_path_factory.mktemp("fast")
    _tree(root)
    texts = ["/".join(parts) for parts, _ in names]
    texts = [str(root) + "/" + t if how == "below the tree" else "/" + t if how == "from /" else t
             for t, (_, how) in zip(texts, names, strict=True)]
    old = os.getcwd()
    os.chdir(root)
    try:
        for resolution in (False, True):
            with one_resolution() if resolution else contextlib.nullcontext():
                finder = ConfigFinder()
                for name in texts * 2:
                    got = finder.for_path(name, directory=False)
                    want = ConfigFinder()._for_path(name, False)
                    assert got.path == want.path, name
                    assert got.relative(name) == _reference_relative(got, name), name
    finally:
        os.chdir(old)


def _reference_holds_lists(path: str) -> bool:
    """``holds_lists`` as written before its fast path: every name asked of its suffixes."""
    if is_project(os.path.basename(path)):
        try:
            return b"<Data " in Path(path).read_bytes()
        except OSError:
            return True
    if not is_xml_name(path):
        return True
    try:
        head = Path(path).read_bytes()[:65536]
    except OSError:
        return True
    return xml_form(head) is not None


@given(st.lists(st.sampled_from(["a", ".", "xml", "XML", "Xml", "tsproj", "TSPROJ", "xti", "lis", "#", "#Achse",
                                 "_", " "]), min_size=1, max_size=6),
       st.sampled_from([b"<other/>", b"<Data x='1'/>", b"", b"\x00\xff"]))
@example(["a", ".", "tsproj", "#Achse"], b"<other/>")  # a project's element by its name: read, and no list
@example(["a", ".", "XML"], b"<other/>")  # an XML file by a suffix in capitals: read, and no list
@settings(max_examples=300, deadline=None)
def test_which_walked_files_hold_lists_is_as_before(tmp_path_factory: pytest.TempPathFactory, parts: list[str],
                                                     content: bytes) -> None:
    """``holds_lists`` answers by the name alone for a file neither XML nor a TwinCAT project by its name,
    and as before for every name and content."""
    folder = tmp_path_factory.mktemp("walked")
    name = "".join(parts)
    if name in (".", "..") or "/" in name:
        return
    path = folder / name
    path.write_bytes(content)
    assert holds_lists(str(path)) == _reference_holds_lists(str(path))


@given(st.lists(st.sampled_from(["a", ".", "..", "/", "lis", "LIS", ".Nc", "x", "ü", " ", "\\\\", "tar.gz"]),
                max_size=8))
@example(["/", ".", "lis"])  # `/.lis`: a hidden name, no suffix
@example(["a", ".", ".", "lis"])  # `a..lis`: `.lis`
@example([".", ".", ".", "lis"])  # `...lis`: only dots before the last one, no suffix
@settings(max_examples=500)
def test_a_names_suffix_is_splitexts(parts: list[str]) -> None:
    """``zero.forms._suffix`` (what every question of a file's name asks) is ``os.path.splitext``'s, lower."""
    name = "".join(parts)
    assert _suffix(name) == os.path.splitext(name)[1].lower()


_CONFIGS = ["", 'per-file-ignores = {"a/*.lis" = ["R001"]}', 'kind = {"*.lis" = "AXIS"}',
            'encoding = {"*.lis" = "utf-8"}', 'extend-per-file-ignores = {"*.lis" = ["R002"]}', 'select = ["R"]']


@pytest.mark.parametrize("parent", _CONFIGS)
@pytest.mark.parametrize("child", _CONFIGS)
@pytest.mark.parametrize("cli", [LintOptions(), LintOptions(kind="CHAN", encoding="latin-1")])
def test_options_without_file_patterns_are_as_before(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, parent: str,
                                                     child: str, cli: LintOptions) -> None:
    """A configuration chain without per-file patterns answers every file's options without asking its name
    (``Config._no_file_patterns``), as asking it would."""
    (tmp_path / "a").mkdir()
    (tmp_path / "zero.toml").write_text(parent + "\n", encoding="utf-8")
    (tmp_path / "a" / "zero.toml").write_text(child + "\n", encoding="utf-8")
    cfg = ConfigFinder().for_path(tmp_path / "a" / "x.lis", directory=False)
    files = [str(tmp_path / "a" / "x.lis"), str(tmp_path / "a" / "y.nc"), "a/x.lis"]
    fast = [cfg.options_for(f, cli) for f in files]
    monkeypatch.setattr(Config, "_no_file_patterns", lambda self: False)
    assert fast == [cfg.options_for(f, cli) for f in files]


_FOLDER_PARTS = st.sampled_from(["d", "e", "to_d", "to_up", "dangling", "loop", "f.lis", ".", "..", "", "none"])


@pytest.fixture(scope="module")
def linked_tree(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Folders, a file and links of every kind: to a folder, to a folder above, dangling, a loop."""
    root = tmp_path_factory.mktemp("resolve")
    (root / "d" / "e" / "d").mkdir(parents=True)
    (root / "d" / "f.lis").write_text("x\n")
    (root / "d" / "to_d").symlink_to(root / "d")
    (root / "d" / "e" / "to_up").symlink_to("../..")
    (root / "d" / "dangling").symlink_to(root / "nowhere")
    (root / "d" / "e" / "loop").symlink_to("loop")
    return root


@given(st.lists(_FOLDER_PARTS, min_size=1, max_size=6), st.booleans())
@settings(max_examples=300, deadline=None)
def test_a_folder_resolved_from_its_parent_is_realpaths(linked_tree: Path, parts: list[str], absolute: bool) -> None:
    """A folder resolved within one command (from its parent's answer and one ``lstat`` of its last part) is
    ``os.path.realpath`` of it, asked in any order, through links, dangling links, loops, ``.``, ``..``,
    doubled separators, names below a file and names that do not exist, relative or absolute."""
    from zero.engine import config as config_module

    name = ("/".join([str(linked_tree), *parts]) if absolute else "/".join(parts)) or "."
    cwd = os.getcwd()
    os.chdir(linked_tree)
    try:
        with one_resolution():
            for upper in range(1, len(parts)):  # the parents first, sometimes: their answers are reused
                if (upper + len(name)) % 2:
                    prefix = "/".join(([str(linked_tree)] if absolute else []) + parts[:upper]) or "."
                    assert config_module._resolved_folder(prefix) == os.path.realpath(prefix)
            assert config_module._resolved_folder(name) == os.path.realpath(name), name
    finally:
        os.chdir(cwd)


def test_a_folder_thousands_of_levels_deep_is_resolved(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A walk can meet folders nested deeper than Python's recursion limit: each is resolved as realpath
    resolves it, from its parent's answer, without a RecursionError."""
    from zero.engine import config as config_module

    monkeypatch.chdir(tmp_path)
    deep = "/".join(["d"] * 1500)
    for level in range(1, 1501):  # (os.makedirs recurses per level)
        os.mkdir("/".join(["d"] * level))
    try:
        with one_resolution():
            assert config_module._resolved_folder(deep) == os.path.realpath(deep)
            assert config_module._resolved_folder(deep + "/..") == os.path.realpath(deep + "/..")
    finally:  # from the bottom up: shutil.rmtree (pytest's clean-up of old temporary folders) recurses per level
        for level in range(1500, 0, -1):
            os.rmdir("/".join(["d"] * level))
