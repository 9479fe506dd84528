"""The VS Code extension (``editors/vscode``): a consistent manifest, the languages it contributes,
the documents it sends the server, its grammars tested on real lines, and its package.

Without npm (only Node): the manifest, the language configurations, the document selector and the
folding of ``folding.js``. With npm: the extension's locked dev dependencies are installed into a
copy of it (``npm ci``), then ``vscode-tmgrammar-test`` checks the ``^`` assertions of
``editors/vscode/test/*.lis|nc``, VS Code's TextMate engine tokenizes every list of the fixtures
(and of the corpus, where there is one) and must agree with zero's tokenizer on every key, value and
comment, and ``vsce package`` writes a ``.vsix``. Each of these skips, with the reason, where Node or
npm is missing or the registry cannot be reached.
"""

from __future__ import annotations

import functools
import itertools
import json
import re
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT, builtin_registry, corpus_dir
from zero.lists.model import Comment, End, Entry
from zero.lists.tokenizer import tokenize
from zero.nc.program import comment_spans, read_program

VSCODE = ROOT / "editors" / "vscode"
NODE = shutil.which("node")
NPM = shutil.which("npm")
needs_node = pytest.mark.skipif(NODE is None, reason="node not installed")


@functools.cache
def manifest() -> dict:
    return json.loads((VSCODE / "package.json").read_text(encoding="utf-8"))


def contributed(kind: str) -> list[dict]:
    return manifest()["contributes"][kind]


def language(lang_id: str) -> dict:
    return next(x for x in contributed("languages") if x["id"] == lang_id)


def read_json(relative: str) -> dict:
    path = VSCODE / relative
    assert path.is_file(), f"{relative} is named in package.json but missing"
    return json.loads(path.read_text(encoding="utf-8"))


# ------------------------------------------------------------------------------------- manifest


def test_manifest_names_existing_valid_files() -> None:
    m = manifest()
    assert (VSCODE / m["main"]).is_file()
    assert {x["id"] for x in contributed("languages")} == {"isg-list", "isg-nc"}
    for lang in contributed("languages"):
        assert isinstance(read_json(lang["configuration"]), dict)
    for grammar in contributed("grammars"):
        raw = read_json(grammar["path"])
        assert raw["scopeName"] == grammar["scopeName"] == f"source.{grammar['language']}"
        assert raw["patterns"] and raw["repository"]
        for include in re.findall(r'"include": "#([^"]+)"', json.dumps(raw, indent=0)):
            assert include in raw["repository"], f"{grammar['path']} includes #{include}, which it lacks"
    for path in ("README.md", "LICENSE", ".vscodeignore", ".gitignore", "package-lock.json"):
        assert (VSCODE / path).is_file(), path
    lock = json.loads((VSCODE / "package-lock.json").read_text(encoding="utf-8"))
    assert lock["packages"][""]["devDependencies"] == m["devDependencies"]
    assert lock["packages"][""]["dependencies"] == m["dependencies"]


def test_languages_are_lists_and_programs_not_xml_or_structured_forms() -> None:
    assert language("isg-list")["extensions"] == [".lis", ".lst"]
    assert language("isg-nc")["extensions"] == [".nc", ".mpf", ".spf"]
    for lang in contributed("languages"):
        assert not {".xml", ".yaml", ".yml", ".toml", ".json"} & set(lang["extensions"])


def test_activates_on_opening_a_list_or_program() -> None:
    events = manifest()["activationEvents"]
    assert {"onLanguage:isg-list", "onLanguage:isg-nc"} <= set(events)
    assert "workspaceContains:**/*.lis" in events


def test_every_contributed_command_is_registered() -> None:
    source = (VSCODE / "extension.js").read_text(encoding="utf-8")
    commands = {c["command"] for c in contributed("commands")}
    assert {"zero.restart", "zero.fixAll", "zero.showEffectiveValue"} <= commands
    for command in commands:
        assert f'"{command}"' in source, f"{command} is contributed but extension.js never names it"
    # the server's commands are called through workspace/executeCommand (the client's middleware)
    assert "middleware: { executeCommand }" in source
    for entry in manifest()["contributes"]["menus"]["commandPalette"]:
        assert entry["command"] in commands
    settings = manifest()["contributes"]["configuration"]["properties"]
    for name in re.findall(r'config\.get\("([A-Za-z]+)"\)', source):
        assert f"zero.{name}" in settings, f"extension.js reads zero.{name}, which package.json does not declare"


def test_language_configurations() -> None:
    lis = read_json(language("isg-list")["configuration"])
    nc = read_json(language("isg-nc")["configuration"])
    assert lis["comments"] == {"lineComment": "#"}  # toggled as `# `, the way S005 wants it
    assert nc["comments"] == {"lineComment": ";", "blockComment": ["(", ")"]}
    assert lis["brackets"] == nc["brackets"] == [["[", "]"]]
    word = re.compile(lis["wordPattern"])
    assert word.match("np_grp[1].achse[0].versch 100").group() == "np_grp[1].achse[0].versch"
    assert word.match("P-AXIS-00177 x").group() == "P-AXIS-00177"
    start, end = (re.compile(lis["folding"]["markers"][k]) for k in ("start", "end"))
    assert start.match("# region Nullpunkte G54") and end.match("# endregion")
    start, end = (re.compile(nc["folding"]["markers"][k]) for k in ("start", "end"))
    assert start.match("N30 $IF V.A.ACTPOS.X > 100") and end.match("N50 $ENDIF")
    assert start.match("$FOR P1 = 1, 10, 1") and end.match("  $ENDFOR")
    assert not start.match("N20 #MSG [\"$IF\"]")


# ------------------------------------------------------------------------- what the server gets


def glob_regex(pattern: str) -> re.Pattern[str]:
    """A VS Code glob pattern (``**``, ``*``, ``?``, ``{a,b}``) as a regular expression."""
    out, i = "", 0
    while i < len(pattern):
        if pattern.startswith("**/", i):
            out, i = out + "(?:.*/)?", i + 3
        elif pattern.startswith("**", i):
            out, i = out + ".*", i + 2
        elif pattern[i] == "*":
            out, i = out + "[^/]*", i + 1
        elif pattern[i] == "?":
            out, i = out + "[^/]", i + 1
        elif pattern[i] == "{":
            close = pattern.index("}", i)
            out += "(?:" + "|".join(map(re.escape, pattern[i + 1:close].split(","))) + ")"
            i = close + 1
        else:
            out, i = out + re.escape(pattern[i]), i + 1
    return re.compile(out + r"\Z")


STUBS = {
    "vscode/index.js": "module.exports = { Uri: class {}, workspace: {}, window: {}, commands: {}, languages: {} };",
    "vscode-languageclient/node.js": "module.exports = { LanguageClient: class {} };",
}


@needs_node
def test_document_selector_sends_lists_and_only_the_list_forms(tmp_path: Path) -> None:
    """The selector extension.js builds from the default settings: lists and programs by language
    and by name, XML and YAML/TOML/JSON only by the settings' narrow patterns."""
    for name, text in STUBS.items():
        (tmp_path / "node_modules" / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "node_modules" / name).write_text(text, encoding="utf-8")
    settings = manifest()["contributes"]["configuration"]["properties"]
    defaults = {k.removeprefix("zero."): v.get("default") for k, v in settings.items()}
    script = ("const ext = require(process.argv[1]); const d = JSON.parse(process.argv[2]);"
              "console.log(JSON.stringify(ext.documentSelector({ get: (k) => d[k] })));")
    run = subprocess.run([NODE, "-e", script, str(VSCODE / "extension.js"), json.dumps(defaults)],
                         capture_output=True, text=True, timeout=60, env={"NODE_PATH": str(tmp_path / "node_modules")})
    assert run.returncode == 0, run.stderr
    selector = json.loads(run.stdout)
    assert all(f.get("scheme") == "file" for f in selector)
    assert {f["language"] for f in selector if "language" in f} == {"isg-list", "isg-nc"}
    patterns = [glob_regex(f["pattern"]) for f in selector if "pattern" in f]

    def sent(path: str) -> bool:
        return any(p.match(path) for p in patterns)

    for path in ("/w/m/listen/achse_x.lis", "/w/m/X.LST", "/w/prog/bohren.nc", "/w/prog/sub.SPF",
                 "/w/machines/mill/achse_x.yaml", "/w/machines/mill/kanal.toml", "/w/machines/mill/nullp.json",
                 "/w/machines/mill/ax_mds_1.xml", "/w/CncKernelRootDir/config/ax_mds_1.xml", "/w/cfg/startup.xml",
                 "/w/cfg/sda_mds1.xml", "/w/upd/axis-Update.xml", "/w/m/listen/kanal.yaml"):
        assert sent(path), path
    for path in ("/w/.github/workflows/ci.yaml", "/w/package.json", "/w/pyproject.toml", "/w/zero.toml",
                 "/w/docs/mkdocs.yml", "/w/.vscode/settings.json", "/w/project/TwinCAT Project.tsproj",
                 "/w/plc/pom.xml", "/w/report.json", "/w/ci/junit.xml"):
        assert not sent(path), path


@needs_node
def test_folding_of_a_list_by_its_comment_blocks() -> None:
    path = FIXTURES / "seed" / "nullp_3achsen.lis"
    lines = path.read_text(encoding="utf-8").splitlines()
    script = ("const f = require(process.argv[1]);"
              "console.log(JSON.stringify(f.foldingRanges(JSON.parse(require('fs').readFileSync(0, 'utf8')))));")
    run = subprocess.run([NODE, "-e", script, str(VSCODE / "folding.js")], input=json.dumps(lines),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    ranges = json.loads(run.stdout)
    starts = [r["start"] for r in ranges]
    assert len(starts) == len(set(starts))  # VS Code keeps one range per start line
    assert ranges[0] == {"start": 0, "end": 10, "kind": "region"}  # the header and its two entries
    g54 = next(r for r in ranges if "'G54'" in lines[r["start"] + 1])
    assert lines[g54["start"]] == "# =====" and lines[g54["end"]].startswith("np_grp[1].achse[2].inaktiv")
    for r in ranges:
        assert lines[r["start"]].startswith("#") and r["end"] > r["start"]
        assert not lines[r["end"]].startswith("#") and lines[r["end"]].strip()
    for a, b in itertools.pairwise(ranges):
        assert a["end"] < b["start"]
    tail = json.loads(subprocess.run([NODE, "-e", script, str(VSCODE / "folding.js")], capture_output=True,
                                     text=True, timeout=60, input=json.dumps(["a 1", "Ende", "b 2", "c 3"])).stdout)
    assert tail == [{"start": 1, "end": 3, "kind": "region"}]


# ------------------------------------------------------------------------------ npm: grammars, vsix


def npm_error(run: subprocess.CompletedProcess[str]) -> str:
    text = [x for x in (run.stderr or run.stdout or "").splitlines() if x.strip() not in ("", "npm error")]
    return " / ".join(text[:3])[:400]  # npm says the code (ECONNREFUSED, E404 …) first


@pytest.fixture(scope="module")
def extension(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A copy of the extension with its locked dependencies installed (``npm ci``, no install
    scripts: keytar's native build is not needed to package)."""
    if NODE is None or NPM is None:
        pytest.skip("npm not installed (the extension's dev dependencies come from npm)")
    root = tmp_path_factory.mktemp("vscode") / "zero-lint"
    shutil.copytree(VSCODE, root, ignore=shutil.ignore_patterns("node_modules", "*.vsix"))
    try:
        run = subprocess.run([NPM, "ci", "--ignore-scripts", "--no-audit", "--no-fund", "--loglevel=error"],
                             cwd=root, capture_output=True, text=True, timeout=600)
    except subprocess.TimeoutExpired:
        pytest.skip("npm ci took more than 10 minutes (registry unreachable?)")
    if run.returncode != 0:
        pytest.skip(f"npm ci failed (registry unreachable?): {npm_error(run)}")
    return root


def npx(root: Path, *args: str, timeout: int = 300) -> subprocess.CompletedProcess[str]:
    return subprocess.run([NPM, "exec", "--no", "--", *args], cwd=root, capture_output=True, text=True,
                          timeout=timeout)


def installed_version(root: Path, package: str) -> str:
    return json.loads((root / "node_modules" / package / "package.json").read_text(encoding="utf-8"))["version"]


def assertion_count(path: Path, comment: str) -> int:
    marker = re.compile(re.escape(comment) + r"\s*(?:\^|<~*-)")
    return sum(1 for line in path.read_text(encoding="utf-8").splitlines() if marker.match(line))


@pytest.mark.slow
def test_grammars_pass_their_scope_assertions(extension: Path) -> None:
    cases = sorted((extension / "test").glob("*.lis")) + sorted((extension / "test").glob("*.nc"))
    assert {p.suffix for p in cases} == {".lis", ".nc"}
    count = sum(assertion_count(p, "#" if p.suffix == ".lis" else ";") for p in cases)
    assert count >= 100
    run = npx(extension, "vscode-tmgrammar-test", "--compact", *(str(p.relative_to(extension)) for p in cases))
    assert run.returncode == 0, run.stdout + run.stderr
    # and the tool does fail a wrong assertion (it did check the lines above)
    bad = extension / "test" / "wrong.lis"
    bad.write_text('# SYNTAX TEST "source.isg-list"\n'
                   "kenngr.swe_pos 1\n"
                   "#              ^ string.quoted.double.isg-list\n", encoding="utf-8")
    try:
        run = npx(extension, "vscode-tmgrammar-test", "--compact", "test/wrong.lis")
    finally:
        bad.unlink()
    assert run.returncode != 0 and "string.quoted.double.isg-list" in run.stdout + run.stderr


def list_files() -> list[Path]:
    files = sorted(FIXTURES.glob("seed/*.lis")) + sorted(FIXTURES.glob("rules/*/*.lis"))
    files += sorted(FIXTURES.glob("machine*/listen/*.lis"))
    corpus = corpus_dir()
    if corpus.is_dir():
        files += sorted(p for p in corpus.rglob("*.lis") if p.stat().st_size < 2_000_000)
    return files


MACHINE_DATA = re.compile(r"#\s*MACHINE\s+DATA\b", re.IGNORECASE)  # as zero.nc.program reads it
VALUE_SCOPES = ("constant.numeric", "constant.other", "constant.language", "string.", "keyword.operator.bitwise")


def utf16(text: str, index: int) -> int:
    """The UTF-16 offset of a column (a stray byte, kept as a lone surrogate, is one unit in JavaScript too)."""
    return index + sum(1 for c in text[:index] if ord(c) > 0xFFFF)


def scopes_at(tokens: list[list], column: int) -> str:
    for start, end, scopes in tokens:
        if start <= column < end:
            return " ".join(scopes)
    return ""


class Agreement:
    """Compares the tokens of one list's lines with zero's reading of them."""

    def __init__(self, name: str, lines: list[str], tokens: list[list[list]]) -> None:
        self.name, self.lines, self.tokens = name, lines, tokens
        self.faults: list[str] = []

    def expect(self, line: int, start: int, end: int, want: str | tuple[str, ...], refuse: str | None = None,
               what: str = "") -> None:
        """Every character but blanks of ``line`` (1-based) in ``start..end`` has a scope containing
        ``want`` (one of them) and none containing ``refuse``; the first that does not is a fault."""
        wants = (want,) if isinstance(want, str) else want
        text = self.lines[line - 1]
        for col in range(start, min(end, len(text))):
            if text[col] in " \t":
                continue
            scopes = scopes_at(self.tokens[line - 1], utf16(text, col))
            if not any(w in scopes for w in wants) or (refuse is not None and refuse in scopes):
                self.faults.append(f"{self.name}:{line}:{col + 1} {what}: {scopes!r} in {text!r}")
                return


@pytest.mark.slow
def test_list_grammar_agrees_with_zeros_tokenizer(extension: Path) -> None:
    """Every line of every list of the fixtures (and the corpus): where zero's tokenizer sees a key,
    a value, a comment, `Ende` and the lines after it, VS Code's TextMate engine sees the same."""
    grammar = str(extension / "syntaxes" / "isg-list.tmLanguage.json")
    checked: dict[str, int] = {"files": 0, "entries": 0, "comments": 0, "after-end": 0}
    faults: list[str] = []
    docs = [(path, tokenize(path.read_bytes(), str(path))) for path in list_files()]
    docs = [(path, doc) for path, doc in docs if not any(p.kind == "binary" for p in doc.problems)]
    run = subprocess.run([NODE, "test/tokenize.js"], cwd=extension, capture_output=True, text=True, timeout=300,
                         input=json.dumps({"grammar": grammar, "documents": [doc.lines for _, doc in docs]}))
    assert run.returncode == 0, run.stderr
    for (path, doc), tokens in zip(docs, json.loads(run.stdout), strict=True):
        checked["files"] += 1
        name = str(path.relative_to(ROOT) if path.is_relative_to(ROOT) else path)
        a = Agreement(name, doc.lines, tokens)
        for item in doc.items:
            if isinstance(item, Comment):
                checked["comments"] += 1
                a.expect(item.line, 0, len(doc.lines[item.line - 1]), "comment", what="comment line")
            elif isinstance(item, End):
                a.expect(item.line, item.start, item.start + 4, "keyword.control.end", what="Ende")
            elif isinstance(item, Entry) and item.after_end:
                checked["after-end"] += 1
                a.expect(item.line, 0, len(doc.lines[item.line - 1]), "comment.block.after-end", what="after Ende")
            elif isinstance(item, Entry):
                checked["entries"] += 1
                a.expect(item.line, item.key_start, item.key_end, "variable.other.key", "comment", "key")
                kind = "string.quoted" if item.value.startswith('"') else VALUE_SCOPES
                a.expect(item.line, item.value_start, item.value_end, kind, "comment", "value")
                a.expect(item.line, item.value_start, item.value_start + 1, "meta.entry", "variable.other.key", "value")
                if item.comment is not None:
                    a.expect(item.line, item.comment_start, len(doc.lines[item.line - 1]), "comment", what="comment")
                if item.annotation is not None:
                    a.expect(item.line, item.annotation_start, item.annotation_start + len(item.annotation),
                             "constant.other.parameter-id", what="annotation")
        faults += a.faults
    assert not faults, f"{len(faults)} lines where the grammar and zero disagree:\n" + "\n".join(faults[:40])
    assert checked["entries"] > 200 and checked["comments"] > 50 and checked["after-end"] > 0, checked


@pytest.mark.slow
def test_program_grammar_agrees_with_zeros_reader(extension: Path) -> None:
    """The NC programs of the fixtures and the grammar test: the comments zero skips (`( … )`, nested,
    unclosed, `; …`, not inside strings) are comments, nothing else is; each `#MACHINE DATA` zero reads
    is one, and each axis word of G98/G99 an address with its number."""
    grammar = str(extension / "syntaxes" / "isg-nc.tmLanguage.json")
    files = [*sorted(FIXTURES.glob("programs/*.nc")), VSCODE / "test" / "program.nc"]
    docs = [(p, [x for x in p.read_text(encoding="utf-8").splitlines() if not re.match(r";\s*(?:\^|<)", x)])
            for p in files]
    run = subprocess.run([NODE, "test/tokenize.js"], cwd=extension, capture_output=True, text=True, timeout=300,
                         input=json.dumps({"grammar": grammar, "documents": [lines for _, lines in docs]}))
    assert run.returncode == 0, run.stderr
    faults: list[str] = []
    checked = {"comments": 0, "machine data": 0, "soft limits": 0}
    for (path, lines), tokens in zip(docs, json.loads(run.stdout), strict=True):
        a = Agreement(str(path.relative_to(ROOT)), lines, tokens)
        for number, line in enumerate(lines, 1):
            spans = comment_spans(line)
            inside = set()
            for start, text in spans:
                checked["comments"] += 1
                a.expect(number, start, start + len(text), "comment", what="comment")
                inside.update(range(start, start + len(text)))
            outside = [c for c in range(len(line)) if c not in inside]
            for col in outside:
                a.expect(number, col, col + 1, "source.isg-nc", "comment", "code")
        program = read_program("\n".join(lines).encode(), str(path), builtin_registry())
        for md in program.machine_data:
            checked["machine data"] += 1
            m = MACHINE_DATA.match(lines[md.line - 1], md.start)
            assert m is not None
            a.expect(md.line, m.start(), m.end(), "keyword.control.directive.machine-data", what="#MACHINE DATA")
        for limit in program.limits:  # the axis words of G98/G99
            checked["soft limits"] += 1
            a.expect(limit.line, limit.start, limit.start + 1, "variable.parameter.address", what="axis")
            a.expect(limit.line, limit.start + 1, limit.end, "constant.numeric", what="axis value")
        faults += a.faults
    assert not faults, f"{len(faults)} lines where the grammar and zero disagree:\n" + "\n".join(faults[:40])
    assert checked["comments"] > 10 and checked["machine data"] > 10 and checked["soft limits"] > 5, checked


@pytest.mark.slow
def test_vsce_packages_the_extension(extension: Path, tmp_path: Path) -> None:
    vsix = tmp_path / "zero-lint.vsix"
    run = npx(extension, "vsce", "package", "--allow-missing-repository", "--out", str(vsix))
    assert run.returncode == 0, run.stdout + run.stderr
    with zipfile.ZipFile(vsix) as z:
        names = set(z.namelist())
        packaged = json.loads(z.read("extension/package.json"))
    assert packaged["version"] == manifest()["version"]
    for path in ("extension.js", "folding.js", "syntaxes/isg-list.tmLanguage.json", "syntaxes/isg-nc.tmLanguage.json",
                 "language-configuration-list.json", "language-configuration-nc.json",
                 "node_modules/vscode-languageclient/package.json"):  # the runtime dependency goes along
        assert f"extension/{path}" in names, path
    assert not [n for n in names if n.startswith(("extension/test/", "extension/node_modules/@vscode/vsce/",
                                                  "extension/node_modules/vscode-tmgrammar-test/"))]
    print(f"vsce {installed_version(extension, '@vscode/vsce')}, vscode-tmgrammar-test "
          f"{installed_version(extension, 'vscode-tmgrammar-test')}: {vsix.name} {vsix.stat().st_size} bytes")
