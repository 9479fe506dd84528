"""Contained and bounded (issue 23): what a received repository, configuration or list can make
zero do. Each case broke a promise of the README's "Files: what zero guarantees" on the old main;
hostile inputs are made here, never committed."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli
from zero.errors import ZeroError

pytestmark = pytest.mark.slow
GIT = shutil.which("git")


@pytest.mark.skipif(GIT is None, reason="git is not installed")
def test_linting_an_untrusted_checkout_runs_none_of_its_code(tmp_path: Path) -> None:
    """README: "Runs nothing a repository configures": `core.fsmonitor` names a
    program that `git ls-files` runs; zero asks git with it switched off."""
    repo = tmp_path / "checkout"
    repo.mkdir()
    env = {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1"}

    def git(*args: str) -> None:
        assert GIT is not None
        subprocess.run([GIT, *args], cwd=repo, env=env, check=True, capture_output=True)

    git("init", "-q")
    (repo / "a.lis").write_text("np_grp[1].achse[0].versch x\nEnde\n")
    (repo / "ignored.lis").write_text("np_grp[1].achse[0].versch x\nEnde\n")
    (repo / ".gitignore").write_text("ignored.lis\n")
    git("add", "a.lis", ".gitignore")
    git("-c", "user.email=t@example.invalid", "-c", "user.name=t", "commit", "-qm", "x")
    marker = tmp_path / "ran"
    hook = tmp_path / "hook.sh"
    hook.write_text(f"#!/bin/sh\ntouch {marker}\necho 0\n")
    hook.chmod(0o755)
    git("config", "core.fsmonitor", str(hook))
    git("config", "core.hooksPath", str(tmp_path))
    run = zero_cli("lint", str(repo), "--output-format", "concise", env=env)
    assert not marker.exists(), "zero ran a program the repository configured"
    assert "a.lis" in run.stdout and "ignored.lis" not in run.stdout  # .gitignore still applies


def _startup(folder: Path, lines: list[str]) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "hochlauf.lis"
    path.write_text("kanal_anzahl 1\n" + "".join(f"{line}\n" for line in lines) + "Ende\n")
    return path


@pytest.mark.parametrize("reference", ["etc/passwd", "../../../../../../etc/passwd", "/etc/passwd", "/etc/hostname",
                                       "proc/self/environ", "/proc/self/environ", "C:\\Windows\\win.ini"])
def test_a_start_up_list_cannot_make_zero_print_a_file_of_this_computer(tmp_path: Path, reference: str) -> None:
    """README: "A start-up list you received cannot make zero read, or print, other files of your
    computer.": the working
    directory is never the file system's root nor above the project, absolute paths are not
    followed (X012), and no line of a file outside the machine appears in any output."""
    startup = _startup(tmp_path / "m", [f"hand_mds {reference}", "sda_mds[0] ./kanal.lis"])
    (tmp_path / "m" / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")
    secrets = [Path("/etc/passwd").read_text(errors="replace").split(":")[0] + ":x:",
               os.environ.get("HOME", "/root"), "PATH=/"]
    for command in (("lint", "--machine", str(startup), "--output-format", "json"),
                    ("show", "--machine", str(startup), "--effective"),
                    ("explain", "kanal_anzahl", "--machine", str(startup))):
        run = zero_cli(*command)
        shown = run.stdout + run.stderr
        assert not any(s in shown for s in secrets), (command, shown[:500])
    lint = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    expected = "X012" if reference.startswith(("/", "C:")) else ("X012" if reference.startswith("..") else "X005")
    assert f"{expected} " in lint.stdout, lint.stdout


def test_a_file_that_is_no_list_is_named_not_printed(tmp_path: Path) -> None:
    folder = tmp_path / "m"
    startup = _startup(folder, ["hand_mds ./credentials.txt", "rtconf_lis ./empty.lis"])
    (folder / "credentials.txt").write_text("user admin\npassword s3cret-value\napi_key AKIA0000SECRET\n")
    (folder / "empty.lis").write_text("# nothing set yet\nEnde\n")
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    assert "s3cret" not in run.stdout + run.stderr and "AKIA" not in run.stdout + run.stderr
    assert "X005 error `hand_mds` names `./credentials.txt`, which is not a parameter list" in run.stdout
    assert "empty.lis" not in run.stdout  # an empty list is a list
    shown = zero_cli("show", "--machine", str(startup))
    assert "s3cret" not in shown.stdout + shown.stderr


def test_the_working_directory_stops_at_the_project(tmp_path: Path) -> None:
    """A start-up list in a project (git work tree or zero configuration) never resolves its lists
    above it, even where a same-named file lies there."""
    project = tmp_path / "project"
    (project / ".git").mkdir(parents=True)
    (tmp_path / "listen").mkdir()
    (tmp_path / "listen" / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")  # above the project
    startup = _startup(project / "listen", ["sda_mds[0] ./listen/kanal.lis"])
    run = zero_cli("show", "--machine", str(startup), "--output-format", "json")
    import json

    data = json.loads(run.stdout)
    assert data["working_directory"] in (str(project), str(project / "listen")), data
    assert [entry["status"] for entry in data["lists"]] == ["missing"]


@pytest.mark.parametrize("entry", ['startup = "/etc/passwd"', '"hand_mds" = "../../../../etc/passwd"',
                                   'working-directory = "/"', 'startup = "../outside/hochlauf.lis"'])
def test_a_received_configuration_names_only_the_projects_files(tmp_path: Path, entry: str) -> None:
    project = tmp_path / "project"
    project.mkdir()
    (project / "zero.toml").write_text(f"[machine]\n{entry}\n")
    (project / "a.lis").write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    run = zero_cli("limits", cwd=project)
    assert run.code == 2 and "lies outside the project" in run.stderr, run
    assert "root:" not in run.stdout + run.stderr


# ------------------------------------------------------------------- bounded: no internal error


def _no_internal_error(run: object) -> None:
    text = run.stdout + run.stderr  # type: ignore[attr-defined]
    assert "internal error" not in text, text[:400]


@pytest.mark.parametrize("command", [("lint",), ("convert",), ("show",), ("diff", "big.toml")])
def test_a_toml_integer_of_any_length_is_a_located_refusal(tmp_path: Path, command: tuple[str, ...]) -> None:
    (tmp_path / "big.toml").write_text('_zero = {kind = "zero"}\n[np_grp.1.achse.0]\nversch = 0x' + "f" * 5000 + "\n")
    run = zero_cli(*command[:1], "big.toml", *command[1:], cwd=tmp_path)
    _no_internal_error(run)
    said = run.stdout if command[0] == "lint" else run.stderr  # lint: one S017 finding, and the run goes on
    assert run.code in (1, 2) and "big.toml:3:10:" in said and "no parameter holds it" in said, run


def test_lengths_beyond_a_float_are_shown_exactly_and_json_stays_json(tmp_path: Path) -> None:
    import json

    huge_hex = "0x" + "f" * 270
    nines = "9" * 60
    (tmp_path / "ax.lis").write_text(f"kenngr.achs_typ 1\nkenngr.swe_pos {huge_hex}\nkenngr.swe_neg -{nines}\nEnde\n")
    (tmp_path / "ax2.lis").write_text("kenngr.achs_typ 1\nkenngr.swe_pos 1\nkenngr.swe_neg -1\nEnde\n")
    for command in (("show", "ax.lis"), ("diff", "ax.lis", "ax2.lis"), ("diff", "--defaults", "ax.lis"),
                    ("diff", "--defaults", "ax.lis", "--output-format", "json"),
                    ("diff", "ax2.lis", "ax.lis", "--output-format", "json"), ("lint", "ax.lis")):
        run = zero_cli(*command, cwd=tmp_path)
        _no_internal_error(run)
        assert run.code in (0, 1), (command, run)
        if "json" in command:
            json.loads(run.stdout)
    shown = zero_cli("diff", "--defaults", "ax.lis", cwd=tmp_path).stdout
    assert "-" + "9" * 60 in shown and "9190283508" not in shown  # as written; no float's wrong digits
    assert "-" + "9" * 56 + ".9999 mm" in zero_cli("show", "ax.lis", cwd=tmp_path).stdout  # exact


def test_limits_of_a_machine_with_lengths_beyond_a_float(tmp_path: Path) -> None:
    import json

    m = tmp_path / "m"
    m.mkdir()
    (m / "hochlauf.lis").write_text("kanal_anzahl 1\nsda_mds[0] ./kanal.lis\nnullp_data[0] ./nullp.lis\n"
                                    "werkz_data[0] ./wz.lis\nzahl_mds 1\nachs_mds[0] ./x.lis\nEnde\n")
    (m / "kanal.lis").write_text("gruppe[0].achs_anzahl 1\ngruppe[0].achse[0].log_achs_nr 1\n"
                                 "gruppe[0].achse[0].bezeichnung X\nEnde\n")
    (m / "x.lis").write_text(f"kopf.achs_nr 1\nkenngr.swe_pos 0x{'f' * 300}\nkenngr.swe_neg -1\nEnde\n")
    (m / "nullp.lis").write_text("np_grp[1].achse[0].versch 0x" + "7" * 280 + "\nEnde\n")
    (m / "wz.lis").write_text("wz[1].ax_versatz[0] 5\nEnde\n")
    for command in (("limits", "--machine", "hochlauf.lis", "--profile", "ip247"),
                    ("limits", "--machine", "hochlauf.lis", "--output-format", "json"),
                    ("lint", "--machine", "hochlauf.lis"), ("show", "--machine", "hochlauf.lis")):
        run = zero_cli(*command, cwd=m)
        _no_internal_error(run)
        assert run.code in (0, 1), (command, run)
        if "json" in command:
            json.loads(run.stdout)


@pytest.mark.parametrize("config", ["ignore = " + "[" * 100_000 + "\n",
                                    "[tool.zero]\nselect = [\"R\"]\n" + ".".join(["a"] * 30_000) + " = 1\n",
                                    'exclude = ["' + "a*" * 100 + '"]\n',
                                    'exclude = ["' + "/".join(["**"] * 50) + '"]\n'])
def test_a_hostile_configuration_is_refused_before_the_work(tmp_path: Path, config: str) -> None:
    """Limits enforced before parsing or matching: nesting, dotted keys, pattern complexity."""
    (tmp_path / "zero.toml").write_text(config)
    (tmp_path / "a.lis").write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    run = zero_cli("lint", "a.lis", cwd=tmp_path, memory_mib=400, timeout=20)
    _no_internal_error(run)
    assert run.code == 2 and "zero.toml" in run.stderr, run
    assert run.seconds < 5, run.seconds


def test_a_start_up_list_naming_one_list_ten_thousand_times(tmp_path: Path) -> None:
    """The catalogue's array (achs_mds[0..63]) bounds what is read, each file is read once, and the
    machine's entries are bounded: 20,001 entries named 64 times are refused where the start-up list
    crosses 500,000, before any rule runs (issue 43)."""
    m = tmp_path / "m"
    m.mkdir()
    (m / "x.lis").write_text("kopf.achs_nr 1\n" + "".join(f"getriebe[0].dynamik.vb_max {i}\n" for i in range(20_000))
                             + "Ende\n")
    (m / "hochlauf.lis").write_text("kanal_anzahl 1\nzahl_mds 10000\n"
                                    + "".join(f"achs_mds[{i}] ./x.lis\n" for i in range(10_000)) + "Ende\n")
    run = zero_cli("lint", "--machine", "hochlauf.lis", "--output-format", "concise", cwd=m, memory_mib=1500,
                   timeout=120)
    _no_internal_error(run)
    assert run.code == 2 and run.stdout == "", run.stdout
    assert "hochlauf.lis:27:1: `achs_mds[24]` brings the machine's lists to more than 500,000 entries" in run.stderr
    assert run.seconds < 60, run.seconds


@pytest.mark.parametrize(("name", "content"), [("blank.lis", b"\n" * 4_100_000), ("x.lis", b"x\n" * 4_100_000),
                                               ("key.lis", b"a" * 3_000_000 + b" 1\n"),
                                               ("key.yaml", b"a: " + b"1" * 2_000_000 + b"\n")])
def test_an_input_no_list_resembles_is_refused_before_it_is_parsed(tmp_path: Path, name: str, content: bytes) -> None:
    """README: "every limit below is checked before the input is parsed or matched": memory is bounded before the
    work (10 MB of blank lines took 1 GB, 10 MB of `x` lines 9 GB and minutes, one 20 MB key 0.9 GB; the
    first two are over the 4,000,000 lines now, the key over the 1 MiB line)."""
    (tmp_path / name).write_bytes(content)
    for command in (("lint", name), ("show", name), ("format", "--check", name), ("convert", name)):
        if command[0] == "format" and not name.endswith(".lis"):
            continue  # format leaves YAML alone
        run = zero_cli(*command, cwd=tmp_path, memory_mib=300, timeout=30)
        _no_internal_error(run)
        assert run.code == 2 and "any parameter list has" in run.stdout + run.stderr, (command, run)
    piped = zero_cli("lint", "-", "--stdin-filename", name, stdin=content, cwd=tmp_path, memory_mib=300)
    assert piped.code == 2 and "any parameter list has" in piped.stderr


def test_a_flood_of_one_finding_is_listed_ten_thousand_times_then_counted(tmp_path: Path) -> None:
    import json

    (tmp_path / "x.lis").write_bytes(b"x\n" * 25_000)
    run = zero_cli("lint", "x.lis", "--output-format", "json", "--select", "S002", cwd=tmp_path)
    found = json.loads(run.stdout)
    assert len(found) == 10_001
    assert found[-1]["line"] == 10_001 and found[-1]["message"].startswith("15000 more S002 findings")


def test_every_promise_a_test_names_is_in_the_readme() -> None:
    """The safety tests name the documented sentence they prove (`README: "…"`, now in the docs
    site's pages); each must be there, word for word, so that the documentation says no more than
    the tests hold, and changes together."""
    import re

    from conftest import ROOT

    def plain(text: str) -> str:
        return " ".join(text.replace("*", "").replace("`", "").split())

    # the README's promises now live in the documentation site's pages (docs/reading-lists.md)
    pages = [ROOT / "README.md", *(ROOT / "docs").rglob("*.md")]
    readme = plain(" ".join(p.read_text(encoding="utf-8") for p in pages))
    quoted = []
    for path in (ROOT / "tests").rglob("*.py"):
        for m in re.finditer(r'README: "([A-Za-z][^"]*)"', path.read_text(encoding="utf-8")):
            quoted.append((path.name, plain(m.group(1))))
    assert len(quoted) >= 6
    missing = [(name, q) for name, q in quoted if q not in readme]
    assert missing == []


def test_x005_says_why_a_list_cannot_be_read_in_a_sentence(tmp_path: Path) -> None:
    """It said "which file is … bytes" and "which symbolic link loop"."""
    folder = tmp_path / "m"
    startup = _startup(folder, ["hand_mds ./loop.lis", "rtconf_lis ./big.lis", "hw_configuration_list ./gone.lis"])
    (folder / "loop.lis").symlink_to(folder / "loop.lis")
    (folder / "big.lis").write_bytes(b"# big\n" * 200)
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "concise", env={"ZERO_MAX_FILE_SIZE": "1000"})
    lines = [line for line in run.stdout.splitlines() if " X005 " in line]
    assert any("`./loop.lis`, which cannot be read: symbolic link loop" in line for line in lines), lines
    assert any("`./big.lis`, which cannot be read: file is 1200 bytes, larger than" in line for line in lines), lines
    assert any("`./gone.lis`, which does not exist" in line for line in lines), lines


def test_windows_separators_in_a_start_up_list(tmp_path: Path) -> None:
    """TwinCAT writes `.\\sda_mds1.lis`: read as `./sda_mds1.lis` (X005 for every list before); `..\\`
    climbing out and a drive letter are not followed (X012)."""
    folder = tmp_path / "m"
    startup = _startup(folder, ["sda_mds[0] .\\kanal.lis", "hand_mds ..\\..\\hand.lis",
                                "rtconf_lis C:\\TwinCAT\\3.1\\Components\\Mc\\CNC\\rtconf.lis"])
    (folder / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    assert " X005 " not in run.stdout, run.stdout
    assert run.stdout.count(" X012 ") == 2, run.stdout


def test_a_drive_letter_path_is_followed_through_the_configured_roots(tmp_path: Path) -> None:
    import json

    project = tmp_path / "machine"
    (project / ".git").mkdir(parents=True)
    (project / "zero.toml").write_text('[machine]\nstartup = "hochlauf.lis"\n'
                                       'roots = { "C:/TwinCAT/3.1/Components/Mc/CNC" = "cnc" }\n')
    (project / "cnc" / "listen").mkdir(parents=True)
    (project / "cnc" / "listen" / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")
    startup = _startup(project, ["sda_mds[0] c:\\twincat\\3.1\\Components\\Mc\\CNC\\listen\\kanal.lis",
                                 "hand_mds c:\\twincat\\3.1\\components\\mc\\cnc\\..\\..\\secret.lis",
                                 "rtconf_lis D:\\other\\rtconf.lis"])
    shown = json.loads(zero_cli("show", "--machine", "hochlauf.lis", "--output-format", "json", cwd=project).stdout)
    status = {entry["key"]: (entry["status"], entry["resolved"]) for entry in shown["lists"]}
    assert status["sda_mds[0]"] == ("loaded", str(project / "cnc" / "listen" / "kanal.lis")), status
    assert status["hand_mds"][0] == "not-checked" and status["rtconf_lis"][0] == "not-checked", status
    lint = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    assert lint.stdout.count(" X012 ") == 2 and " X005 " not in lint.stdout, lint.stdout
    (project / "zero.toml").write_text('[machine]\nroots = { "C:/TwinCAT" = "../.." }\n')
    refused = zero_cli("limits", "--machine", "hochlauf.lis", cwd=project)
    assert refused.code == 2 and "lies outside the project" in refused.stderr, refused


# ------------------------------------------------------------------ git (issue 43): one module, one set


def _git_env(tmp_path: Path) -> dict[str, str]:
    return {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1", "GIT_AUTHOR_NAME": "t",
            "GIT_AUTHOR_EMAIL": "t@example.invalid", "GIT_COMMITTER_NAME": "t",
            "GIT_COMMITTER_EMAIL": "t@example.invalid", "HOME": str(tmp_path)}


def _partial_clone(tmp_path: Path) -> tuple[Path, Path]:
    """A machine in a partial clone (`--filter=blob:none`) whose promisor remote is ssh and whose
    `core.sshCommand` leaves a marker: any lazy fetch of the missing blob would run it. No network."""
    assert GIT is not None
    env = _git_env(tmp_path)
    origin = tmp_path / "origin"
    shutil.copytree(FIXTURES / "machine-clean", origin)

    def git(*args: str, cwd: Path = origin) -> None:
        assert GIT is not None
        subprocess.run([GIT, *args], cwd=cwd, env=env, check=True, capture_output=True)

    git("init", "-q")
    git("config", "uploadpack.allowFilter", "true")
    git("add", ".")
    git("commit", "-qm", "one")
    with (origin / "listen" / "hochlauf.lis").open("a") as f:
        f.write("# changed\n")
    git("commit", "-qam", "two")
    clone = tmp_path / "clone"
    git("clone", "-q", "--no-local", "--filter=blob:none", f"file://{origin}", str(clone), cwd=tmp_path)
    marker = tmp_path / "PWNED"
    git("config", "remote.origin.url", "ssh://example.invalid/machine", cwd=clone)
    git("config", "core.sshCommand", f"touch {marker}; false", cwd=clone)
    return clone, marker


@pytest.mark.skipif(GIT is None, reason="git is not installed")
def test_a_partial_clone_never_fetches_and_runs_no_command_it_configures(tmp_path: Path) -> None:
    """README: "never fetches a missing object". Issue 43: `zero report --against HEAD~1` in a partial clone
    with an ssh promisor remote ran `core.sshCommand` (git fetched the missing blob lazily). Now
    nothing is fetched: zero says the content is not in the repository, and stops."""
    clone, marker = _partial_clone(tmp_path)
    run = zero_cli("report", "--machine", "listen/hochlauf.lis", "--against", "HEAD~1", "-o", "r.html", cwd=clone,
                   env=_git_env(tmp_path))
    assert not marker.exists(), "zero let git run the repository's core.sshCommand"
    assert run.code == 2 and "zero fetches nothing" in run.stderr, run
    assert not (clone / "r.html").exists()
    # the walk of the same clone asks git too: still nothing runs
    zero_cli("lint", str(clone), "--output-format", "concise", env=_git_env(tmp_path))
    assert not marker.exists()


def test_every_git_call_carries_every_protection(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every git call zero makes (the walk's ignore rules, a revision's files) goes through
    zero.engine.git.run (the architecture test allows no other module to start a program); a `git`
    that records how it is called sees every protection on every call, whatever the caller's
    environment says."""
    import json
    import sys

    from zero.engine import git as zgit

    log = tmp_path / "calls.jsonl"
    fake = tmp_path / "bin" / "git"
    fake.parent.mkdir()
    fake.write_text(f"#!{sys.executable}\nimport json, os, sys\n"
                    f"open({str(log)!r}, 'a').write(json.dumps([sys.argv[1:], dict(os.environ)]) + '\\n')\n"
                    "sys.exit(1)\n")
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", f"{fake.parent}{os.pathsep}{os.environ['PATH']}")
    for name, value in (("GIT_DIR", "/elsewhere"), ("GIT_SSH_COMMAND", "touch x"), ("GIT_ASKPASS", "touch y"),
                        ("SSH_ASKPASS", "touch z"), ("GIT_CONFIG_PARAMETERS", "'core.fsmonitor'='touch w'"),
                        ("GIT_EXTERNAL_DIFF", "touch v"), ("GIT_ALLOW_PROTOCOL", "ssh")):
        monkeypatch.setenv(name, value)
    (tmp_path / "m").mkdir()
    zgit.visible_files(tmp_path / "m")
    with pytest.raises(ZeroError):
        zgit.revision_reader(tmp_path / "m" / "hochlauf.lis", "HEAD~1")
    calls = [json.loads(line) for line in log.read_text().splitlines()]
    assert len(calls) >= 2
    for argv, env in calls:
        settings = {argv[i + 1] for i, a in enumerate(argv) if a == "-c"}
        assert set(zgit.SAFE_CONFIG) <= settings, argv
        assert "protocol.allow=never" in settings and "core.sshCommand=false" in settings
        assert {k: v for k, v in env.items() if k.startswith("GIT_")} == \
            {k: v for k, v in zgit.SAFE_ENV.items() if k.startswith("GIT_")}, argv
        assert "SSH_ASKPASS" not in env and env["GIT_NO_LAZY_FETCH"] == "1"


def _ignored_repo(tmp_path: Path) -> Path:
    assert GIT is not None
    repo = tmp_path / "repo"
    repo.mkdir()
    subprocess.run([GIT, "init", "-q"], cwd=repo, env=_git_env(tmp_path), check=True)
    for name in ("a.lis", "ignored.lis"):
        (repo / name).write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    return repo


@pytest.mark.skipif(GIT is None or not hasattr(os, "mkfifo"), reason="git and FIFOs needed")
@pytest.mark.parametrize("where", [".gitignore", "sub/.gitignore", ".git/info/exclude", "core.excludesFile",
                                   "xdg"])
def test_a_fifo_as_an_ignore_file_never_stalls_and_is_said(tmp_path: Path, where: str) -> None:
    """Issue 43: a FIFO as `.gitignore`, `.git/info/exclude` or `core.excludesFile` stalled the walk
    60 s, then the ignored file was linted without a note. Now zero sees it before git would wait,
    and says that the ignore rules are not applied."""
    repo = _ignored_repo(tmp_path)
    env = _git_env(tmp_path)
    (repo / ".gitignore").write_text("ignored.lis\n")
    if where == "core.excludesFile":
        os.mkfifo(tmp_path / "excludes")
        assert GIT is not None
        subprocess.run([GIT, "config", "core.excludesFile", str(tmp_path / "excludes")], cwd=repo, env=env, check=True)
    elif where == "xdg":
        (tmp_path / "xdg" / "git").mkdir(parents=True)
        os.mkfifo(tmp_path / "xdg" / "git" / "ignore")
        env["XDG_CONFIG_HOME"] = str(tmp_path / "xdg")
    else:
        (repo / where).parent.mkdir(parents=True, exist_ok=True)
        (repo / where).unlink(missing_ok=True)
        os.mkfifo(repo / where)
    run = zero_cli("lint", str(repo), "--output-format", "concise", env=env, timeout=30)
    assert run.seconds < 20, run
    assert ".gitignore not applied" in run.stderr and "FIFO" in run.stderr, run


@pytest.mark.skipif(GIT is None or not hasattr(os, "geteuid") or os.geteuid() != 0,
                    reason="needs git and root to give the repository another owner")
def test_a_repository_git_refuses_is_said_not_silently_unignored(tmp_path: Path) -> None:
    """Issue 43: in a repository owned by another user git refuses to work (its safe.directory) and
    `.gitignore` was dropped silently. zero does not override git's protection: it says so."""
    repo = _ignored_repo(tmp_path)
    (repo / ".gitignore").write_text("ignored.lis\n")
    for p in (repo, *repo.rglob("*")):
        os.lchown(p, 1234, 1234)
    run = zero_cli("lint", str(repo), "--output-format", "concise", env=_git_env(tmp_path))
    assert ".gitignore not applied: git refuses this repository" in run.stderr, run
    assert "safe.directory" in run.stderr


# ------------------------------------------------- containment (issue 43): every path resolved once

SECRET = "SECRET_X"


def _secret_axis(folder: Path) -> tuple[Path, Path]:
    """An axis list and a TwinCAT axis export outside the project, whose axis name is the secret."""
    folder.mkdir(parents=True, exist_ok=True)
    xml = folder / "axis_x.xml"
    xml.write_text((FIXTURES / "twincat" / "axis_x.xml").read_text().replace("X_Achse", SECRET))
    lis = folder / "achse.lis"
    lis.write_text(f"kopf.achs_nr 1\nkopf.log_achs_name {SECRET}\nkenngr.achs_typ 1\nEnde\n")
    return lis, xml


def _machine_with_a_link_out(tmp_path: Path, form: str) -> tuple[Path, Path]:
    """(the folder to run in, the start-up list) of a machine whose folder holds a symbolic link to a
    file outside the project, named in ``form``."""
    lis, xml = _secret_axis(tmp_path / "outside")
    project = tmp_path / "project"
    (project / ".git").mkdir(parents=True)
    m = project / "m"
    m.mkdir()
    (m / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")
    lines = ["kanal_anzahl 1", "zahl_mds 1", "sda_mds[0] ./kanal.lis"]
    if form == "twincat-export-beside":
        shutil.copy(FIXTURES / "twincat" / "cnc_task.xml", m / "startup.xml")
        (m / "axis.xml").symlink_to(xml)
        return project, m / "startup.xml"
    if form in ("element", "override-element"):
        (m / "ax.xml").symlink_to(xml)
        ref = "./ax.xml#AchsMds"
    elif form == "element-through-folder":
        (m / "d").symlink_to(xml.parent, target_is_directory=True)
        ref = "./d/axis_x.xml#AchsMds"
    else:
        (m / "ax.lis").symlink_to(lis)
        ref = "./ax.lis"
    if form.startswith("override"):
        (project / "pyproject.toml").write_text(f'[tool.zero.machine]\nstartup = "m/hochlauf.lis"\n'
                                                f'"achs_mds[0]" = "m/{ref[2:]}"\n')
        lines.append("achs_mds[0] ./kanal.lis")
    else:
        lines.append(f"achs_mds[0] {ref}")
    startup = m / "hochlauf.lis"
    startup.write_text("\n".join(lines) + "\nEnde\n")
    return project, startup


MACHINE_COMMANDS = [("lint", "--machine", "{s}", "--output-format", "json"),
                    ("show", "--machine", "{s}", "--effective"),
                    ("show", "--machine", "{s}", "--output-format", "json"),
                    ("explain", "kopf.log_achs_name", "--machine", "{s}"), ("limits", "--machine", "{s}"),
                    ("report", "--machine", "{s}")]


@pytest.mark.parametrize("form", ["plain", "element", "element-through-folder", "override-plain", "override-element",
                                  "twincat-export-beside"])
def test_a_link_in_the_machine_folder_never_leads_out_in_any_form(tmp_path: Path, form: str) -> None:
    """README: "every path is resolved once, links followed, in every form". Issue 43: a symbolic link in
    the machine's folder to a file outside the project was followed when the reference carried an
    `#Element` suffix (also as a `[tool.zero.machine]` override), and a linked `*.xml` beside a TwinCAT
    start-up export was read: zero printed the outside file. Every command, every form: never."""
    project, startup = _machine_with_a_link_out(tmp_path, form)
    for command in MACHINE_COMMANDS:
        run = zero_cli(*(a.format(s=str(startup)) for a in command), cwd=project)
        assert SECRET not in run.stdout + run.stderr, (form, command, (run.stdout + run.stderr)[:800])


@pytest.mark.parametrize("reference", ["./.bashrc", "./d/.bashrc", "../../../.bashrc", "../.bashrc"])
def test_without_a_project_marker_zero_never_climbs_above_the_start_up_lists_folder(tmp_path: Path,
                                                                                   reference: str) -> None:
    """Issue 43: with no project marker above, the working-directory search climbed up to 4 folders
    and `zero show --machine h/d/x/l/h.lis` printed `h/.bashrc`. Now an ancestor is the working directory
    only along the vendor's layout (`./listen/…` named from inside `listen/`)."""
    home = tmp_path / "h"
    (home / "d" / "x" / "l").mkdir(parents=True)
    for where in (home, home / "d", home / "d" / "x"):
        (where / ".bashrc").write_text(f"kopf.achs_nr 1\nkopf.log_achs_name {SECRET}\nEnde\n")
    startup = home / "d" / "x" / "l" / "h.lis"
    startup.write_text(f"kanal_anzahl 1\nzahl_mds 1\nachs_mds[0] {reference}\nEnde\n")
    for command in MACHINE_COMMANDS:
        run = zero_cli(*(a.format(s="h/d/x/l/h.lis") for a in command), cwd=tmp_path)
        assert SECRET not in run.stdout + run.stderr, (command, (run.stdout + run.stderr)[:800])


def test_the_vendors_layout_still_climbs_into_listen(tmp_path: Path) -> None:
    """The vendor's start-up lists name `./listen/…` from inside `listen/` (and `listen/SoE/`): that
    climb stays, without a project marker."""
    import json

    listen = tmp_path / "machine" / "listen"
    (listen / "SoE").mkdir(parents=True)
    (listen / "kanal.lis").write_text("gruppe[0].achs_anzahl 0\nEnde\n")
    (listen / "SoE" / "achse.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    (listen / "SoE" / "hochlauf.lis").write_text("kanal_anzahl 1\nzahl_mds 1\nsda_mds[0] ./listen/kanal.lis\n"
                                                 "achs_mds[0] ./listen/SoE/achse.lis\nEnde\n")
    shown = json.loads(zero_cli("show", "--machine", "listen/SoE/hochlauf.lis", "--output-format", "json",
                                cwd=tmp_path / "machine").stdout)
    assert {e["key"]: e["status"] for e in shown["lists"]} == {"sda_mds[0]": "loaded", "achs_mds[0]": "loaded"}


def test_a_fleet_folder_walk_never_follows_a_link_out(tmp_path: Path) -> None:
    """Issue 43: `zero diff --fleet GOLDEN FOLDER` walked `/` through a symbolic link in the folder.
    The walk stays in the folder: links to folders are not followed, a start-up list linking out is
    not taken."""
    golden = tmp_path / "golden"
    shutil.copytree(FIXTURES / "machine-clean" / "listen", golden)
    for f in golden.iterdir():
        f.write_text(f.read_text().replace("./listen/", "./"))
    fleet = tmp_path / "fleet"
    shutil.copytree(golden, fleet / "m1")
    (fleet / "root").symlink_to("/", target_is_directory=True)
    (fleet / "out").symlink_to(tmp_path / "elsewhere", target_is_directory=True)
    shutil.copytree(golden, tmp_path / "elsewhere" / "m9")
    (fleet / "m2").mkdir()
    (fleet / "m2" / "hochlauf.lis").symlink_to(golden / "hochlauf.lis")
    run = zero_cli("diff", "--fleet", str(golden / "hochlauf.lis"), str(fleet), timeout=60)
    assert run.seconds < 30, run
    assert "1 machine compared" in run.stdout + run.stderr, run


def test_every_test_the_readmes_safety_table_names_exists() -> None:
    """The README's Safety section names, for each guarantee, the tests that prove it: each exists."""
    import re

    from conftest import ROOT

    section = (ROOT / "README.md").read_text(encoding="utf-8").split("## Safety", 1)[1].split("\n## ", 1)[0]
    named = 0
    for row in section.splitlines():
        if not row.startswith("| ") or "::" not in row:
            continue
        current = None
        for m in re.finditer(r"`(tests/[\w/]+\.py)?::(\w+)`", row):
            current = m.group(1) or current
            assert current is not None, row
            source = (ROOT / current).read_text(encoding="utf-8")
            assert re.search(rf"^(?:async )?def {m.group(2)}\(", source, re.M), m.group(0)
            named += 1
    assert named >= 15


def test_a_machine_read_from_an_export_element_is_read_again_when_the_export_changes(tmp_path: Path) -> None:
    """The resolver's cache signs a machine by the files it was read from; `export.xml#AchsMds` is
    resolved to the export itself (the signature was that of a file that does not exist, so an
    edited export was never read again)."""
    from conftest import builtin_registry
    from zero.engine.project import Project

    m = tmp_path / "m"
    m.mkdir()
    (m / ".git").mkdir()
    export = m / "axis_x.xml"
    export.write_text((FIXTURES / "twincat" / "axis_x.xml").read_text())
    startup = m / "hochlauf.lis"
    startup.write_text("kanal_anzahl 1\nzahl_mds 1\nachs_mds[0] ./axis_x.xml#AchsMds\nEnde\n")
    registry = builtin_registry()
    project = Project(lambda _d: registry, machine=startup)
    first = project.machine(required=True)
    assert first is not None and first.axis_lists[0].text("P-AXIS-00297") == "X_Achse"
    export.write_text(export.read_text().replace("X_Achse", "Y_Achse_longer"))
    again = project.machine(required=True)
    assert again is not None and again.axis_lists[0].text("P-AXIS-00297") == "Y_Achse_longer"
