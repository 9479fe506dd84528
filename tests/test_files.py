"""The fault suite of ``zero.files``: never harm a file, never hang, through the real CLI.

Every case runs the real command line in a child process with a time and address-space
bound (``conftest.zero_cli``): special files, links, owners and modes, read-only files
without the capability to override permissions, racing writers, killed writers,
unreadable files in a walked directory, and patches that ``git apply`` must accept.
"""

from __future__ import annotations

import os
import shutil
import signal
import stat
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from conftest import FIXTURES, zero_cli
from zero.errors import ZeroError
from zero.files import read_file, remove_stale_temps, write_atomic

pytestmark = pytest.mark.slow

LIST = b"np_grp[1].achse[0].versch 100\nEnde\n"
# cp1252, CRLF, a byte that is not UTF-8 (0xB5 = µ), and two safe fixes (S005, S004)
CP1252 = ("# Nullpunkte in µm\r\n#np_grp[1].achse[1].versch 5\r\nnp_grp[1].achse[0]. inaktiv 0\r\n"
          "np_grp[1].achse[0].versch 100   ( 0.01 mm in µm )\r\nEnde\r\n").encode("cp1252")
QUICK = 10.0  # seconds: "at once"


def fifo(path: Path) -> Path:
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs on this platform")
    os.mkfifo(path)
    return path


# ------------------------------------------------------------------------------ reading


@pytest.mark.parametrize("command", [
    ["lint", "{f}"], ["format", "{f}"], ["format", "--check", "{f}"], ["diff", "{f}", "{other}"],
    ["convert", "{f}", "--to", "yaml"], ["show", "{f}"], ["lint", "--machine", "{f}"],
])
def test_a_fifo_named_as_a_file_is_refused_at_once(tmp_path: Path, command: list[str]) -> None:
    """README: "A FIFO, device, socket or directory named as a file is refused at once (nothing blocks), exit 2"."""
    f = fifo(tmp_path / "fifo.lis")
    other = tmp_path / "other.lis"
    other.write_bytes(LIST)
    run = zero_cli(*(a.format(f=f, other=other) for a in command), timeout=QUICK)
    assert run.code == 2, run
    assert "a FIFO (named pipe), not a regular file" in run.stderr
    assert run.stderr.count("\n") == 1


def test_a_device_is_refused_and_memory_stays_bounded() -> None:
    run = zero_cli("lint", "/dev/zero", timeout=QUICK, memory_mib=512)
    assert run.code == 2
    assert run.stderr == "zero: /dev/zero: is a character device, not a regular file; zero reads regular " \
                         "files and standard input (-)\n"


def test_a_device_node_is_neither_read_nor_replaced(tmp_path: Path) -> None:
    node = tmp_path / "node.lis"
    try:
        os.mknod(node, stat.S_IFCHR | 0o600, os.makedev(1, 7))  # /dev/full's numbers
    except (PermissionError, AttributeError):
        pytest.skip("mknod needs privileges this machine does not give")
    src = tmp_path / "a.lis"
    src.write_bytes(LIST)
    assert zero_cli("lint", str(node), timeout=QUICK).code == 2
    run = zero_cli("convert", str(src), "--to", "yaml", "-o", str(node), "--force", timeout=QUICK)
    assert run.code == 2 and "is a character device, not a regular file: not replaced" in run.stderr
    assert stat.S_ISCHR(os.lstat(node).st_mode)


def test_dev_null_and_standard_output_are_written_to_as_meant(tmp_path: Path) -> None:
    """README: "-o /dev/null and a terminal are written to"."""
    src = tmp_path / "a.lis"
    src.write_bytes(LIST)
    run = zero_cli("convert", str(src), "--to", "yaml", "-o", os.devnull, "--force")
    assert run.code == 0, run
    assert stat.S_ISCHR(os.stat(os.devnull).st_mode)
    assert zero_cli("convert", str(src), "--to", "yaml", "-o", "-").out.startswith(b"np_grp:")


def test_an_input_over_the_size_limit_is_refused(tmp_path: Path) -> None:
    """README: "so is an input over 256 MiB"."""
    big = tmp_path / "big.lis"
    big.write_bytes(LIST * 20)
    run = zero_cli("lint", str(big), env={"ZERO_MAX_FILE_SIZE": "100"})
    assert run.code == 2
    assert "larger than the 100 bytes zero reads" in run.stdout  # an F001 finding of that file
    run = zero_cli("lint", "-", "--stdin-filename", "x.lis", stdin=LIST * 20, env={"ZERO_MAX_FILE_SIZE": "100"})
    assert run.code == 2 and "standard input is larger than the 100 bytes zero reads" in run.stderr
    assert zero_cli("lint", str(big), env={"ZERO_MAX_FILE_SIZE": "lots"}).code == 2


def test_unreadable_files_in_a_walked_directory_do_not_stop_the_others(tmp_path: Path) -> None:
    """README: "In a directory walk, a file that cannot be read (dangling link, link loop, FIFO,
    permission) is one F001 finding"."""
    (tmp_path / "good.lis").write_bytes(b"np_grp[97].achse[0].versch 1\nEnde\n")
    (tmp_path / "dangling.lis").symlink_to(tmp_path / "gone.lis")
    (tmp_path / "loop.lis").symlink_to(tmp_path / "loop.lis")
    fifo(tmp_path / "pipe.lis")
    run = zero_cli("lint", str(tmp_path), "--output-format", "concise", timeout=QUICK)
    assert run.code == 2, run
    lines = run.stdout.splitlines()
    assert any("good.lis:1:1: R003" in line for line in lines)
    assert not any("good.lis" in line and "F001" in line for line in lines)  # a readable file: no F001
    assert f"{tmp_path / 'dangling.lis'}:1:1: F001 error dangling symbolic link: its target does not exist: " \
           "not checked" in lines
    assert f"{tmp_path / 'loop.lis'}:1:1: F001 error symbolic link loop (too many levels of symbolic links): " \
           "not checked" in lines
    assert f"{tmp_path / 'pipe.lis'}:1:1: F001 error is a FIFO (named pipe), not a regular file; zero reads " \
           "regular files and standard input (-): not checked" in lines


def test_a_dangling_link_or_loop_named_on_the_command_line_is_refused(tmp_path: Path) -> None:
    (tmp_path / "dangling.lis").symlink_to(tmp_path / "gone.lis")
    run = zero_cli("lint", str(tmp_path / "dangling.lis"))
    assert run.code == 2 and "dangling symbolic link" in run.stderr
    (tmp_path / "loop.lis").symlink_to(tmp_path / "loop.lis")
    for command in (["lint"], ["convert", "--to", "yaml"], ["format"]):
        run = zero_cli(*command, str(tmp_path / "loop.lis"))
        assert run.code == 2 and "symbolic link loop" in run.stderr, (command, run)


# ------------------------------------------------------------------------------ writing


def test_a_symlink_is_written_through_and_stays_a_link(tmp_path: Path) -> None:
    """README: "A symbolic link is written through and stays a link"."""
    src = tmp_path / "a.lis"
    src.write_bytes(LIST)
    real = tmp_path / "real.yaml"
    real.write_bytes(b"old\n")
    link = tmp_path / "link.yaml"
    link.symlink_to(real)
    assert zero_cli("convert", str(src), "-o", str(link), "--force").code == 0
    assert link.is_symlink() and real.read_bytes().startswith(b"np_grp:")

    target = tmp_path / "target.lis"
    target.write_bytes(b"np_grp[1].achse[0]. inaktiv 0\nEnde\n")
    list_link = tmp_path / "list.lis"
    list_link.symlink_to(target)
    run = zero_cli("lint", "--fix", str(list_link))
    assert list_link.is_symlink(), run
    assert target.read_bytes() == b"np_grp[1].achse[0].inaktiv 0\nEnde\n"


def test_format_keeps_hard_links_owner_group_and_mode(tmp_path: Path) -> None:
    f = tmp_path / "a.lis"
    f.write_bytes(b"np_grp[1].achse[0].versch   100\nEnde\n")
    other = tmp_path / "b.lis"
    os.link(f, other)
    os.chmod(f, 0o640)
    if os.geteuid() == 0:
        os.chown(f, 1234, 2345)
    before = os.stat(f)
    run = zero_cli("format", str(f))
    assert run.code == 0, run
    after = os.stat(f)
    assert (after.st_ino, after.st_nlink) == (before.st_ino, 2)
    assert other.read_bytes() == f.read_bytes() != b"np_grp[1].achse[0].versch   100\nEnde\n"
    assert (after.st_uid, after.st_gid, stat.S_IMODE(after.st_mode)) == (before.st_uid, before.st_gid, 0o640)


def test_fix_keeps_the_owner_of_a_single_file(tmp_path: Path) -> None:
    if os.geteuid() != 0:
        pytest.skip("giving a file another owner needs root")
    f = tmp_path / "a.lis"
    f.write_bytes(b"np_grp[1].achse[0]. inaktiv 0\nEnde\n")
    os.chown(f, 1234, 2345)
    os.chmod(f, 0o604)
    assert zero_cli("lint", "--fix", str(f)).code == 0
    st = os.stat(f)
    assert (st.st_uid, st.st_gid, stat.S_IMODE(st.st_mode)) == (1234, 2345, 0o604)
    assert f.read_bytes() == b"np_grp[1].achse[0].inaktiv 0\nEnde\n"


def _without_dac_override() -> tuple[str, ...]:
    capsh = shutil.which("capsh")
    if capsh is None or os.geteuid() != 0:
        pytest.skip("needs root and capsh to drop the capability to override file permissions")
    probe = subprocess.run([capsh, "--drop=cap_dac_override,cap_fowner,cap_dac_read_search", "--", "-c", "true"],
                           capture_output=True, check=False)
    if probe.returncode != 0:
        pytest.skip(f"this machine does not allow dropping capabilities: {probe.stderr[-200:]!r}")
    return (capsh, "--drop=cap_dac_override,cap_fowner,cap_dac_read_search", "--", "-c")


def test_a_read_only_file_is_refused_without_the_capability_to_override(tmp_path: Path) -> None:
    prefix = _without_dac_override()
    for command, original in ((["lint", "--fix"], b"np_grp[1].achse[0]. inaktiv 0\nEnde\n"),
                              (["format"], b"np_grp[1].achse[0].versch   100\nEnde\n")):
        f = tmp_path / f"ro-{command[0]}.lis"
        f.write_bytes(original)
        os.chmod(f, 0o444)
        run = zero_cli(*command, str(f), prefix=prefix)
        assert run.code == 2, (command, run)
        assert "not writable (permission denied): not replaced" in run.stderr
        assert f.read_bytes() == original and stat.S_IMODE(os.stat(f).st_mode) == 0o444


def test_racing_writers_without_force_cannot_both_win(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """README: "without --force an existing file is never replaced, even by two commands racing for one
    name". All writers have their content ready before any claims the name; exactly one wins."""
    target = tmp_path / "out.yaml"
    writers = 6
    barrier = threading.Barrier(writers)
    real_fsync = os.fsync
    waited = threading.local()

    def fsync_then_wait(fd: int) -> None:
        real_fsync(fd)
        if threading.current_thread() is not threading.main_thread() and not getattr(waited, "done", False):
            waited.done = True  # the temporary file's fsync: the content is ready, the name not claimed
            barrier.wait(timeout=10)

    monkeypatch.setattr(os, "fsync", fsync_then_wait)
    outcomes: list[str] = []

    def write(n: int) -> None:
        try:
            write_atomic(target, f"writer {n}\n".encode())
            outcomes.append("won")
        except ZeroError as exc:
            outcomes.append(str(exc))

    threads = [threading.Thread(target=write, args=(n,)) for n in range(writers)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(20)
    assert outcomes.count("won") == 1, outcomes
    assert all("already exists" in o for o in outcomes if o != "won")
    assert target.read_bytes().startswith(b"writer ")
    assert [p.name for p in tmp_path.iterdir()] == ["out.yaml"]


def test_racing_convert_processes_without_force(tmp_path: Path) -> None:
    src = tmp_path / "a.lis"
    src.write_bytes(LIST)
    out = tmp_path / "out.yaml"
    procs = [subprocess.Popen([sys.executable, "-m", "zero", "convert", str(src), "-o", str(out)],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE) for _ in range(4)]
    codes = [p.wait(60) for p in procs]
    assert codes.count(0) == 1 and codes.count(2) == 3, codes


def _slow_writer(target: Path) -> subprocess.Popen[bytes]:
    script = (
        "import os, signal, sys, time\n"
        # as from a terminal: a shell's background job starts with SIGINT ignored, and Python then leaves it so
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "from pathlib import Path\n"
        "import zero.files as f\n"
        "def slow(fd):\n"
        "    sys.stdout.write('writing\\n'); sys.stdout.flush(); time.sleep(30)\n"
        "os.fsync = slow\n"
        f"f.write_atomic(Path({str(target)!r}), b'x' * 1_000_000, force=True)\n"
    )
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout is not None
    assert proc.stdout.readline() == b"writing\n"
    return proc


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_removes_the_temporary_file(tmp_path: Path, signum: int) -> None:
    target = tmp_path / "out.lis"
    target.write_bytes(b"old\n")
    proc = _slow_writer(target)
    proc.send_signal(signum)
    code = proc.wait(20)
    if signum == signal.SIGTERM:
        assert code == 128 + signal.SIGTERM
        assert proc.stderr is not None and b"nothing was replaced" in proc.stderr.read()
    assert [p.name for p in tmp_path.iterdir()] == ["out.lis"]
    assert target.read_bytes() == b"old\n"


def test_a_killed_writers_temporary_file_is_removed_by_the_next_write(tmp_path: Path) -> None:
    """README: "one left by a killed process is removed by the next write"."""
    target = tmp_path / "out.lis"
    target.write_bytes(b"old\n")
    proc = _slow_writer(target)
    proc.kill()
    proc.wait(20)
    assert target.read_bytes() == b"old\n"
    left = [p for p in tmp_path.iterdir() if p.name != "out.lis"]
    assert len(left) == 1 and left[0].name.startswith(f".out.lis.zero-{proc.pid}-")
    write_atomic(target, b"new\n", force=True)
    assert [p.name for p in tmp_path.iterdir()] == ["out.lis"]
    assert target.read_bytes() == b"new\n"
    # a temporary file of a process that still runs is left alone
    live = tmp_path / f".out.lis.zero-{os.getppid()}-0123abcd.tmp"
    live.write_bytes(b"")
    assert remove_stale_temps(target) == []


# ---------------------------------------------------------------------------- --diff


def _git(*args: str, cwd: Path) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, check=False)


@pytest.mark.parametrize("command", [["lint", "--diff"], ["lint", "--fix", "--diff"], ["format", "--diff"]])
def test_a_diff_only_shows_and_git_apply_takes_it(tmp_path: Path, command: list[str]) -> None:
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    _git("init", "-q", cwd=tmp_path)
    f = tmp_path / "nullp.lis"
    f.write_bytes(CP1252)
    run = zero_cli(*command, "nullp.lis", cwd=tmp_path)
    assert run.code == 1, run
    assert f.read_bytes() == CP1252  # --diff never writes
    assert run.out.startswith(b"--- a/nullp.lis\n+++ b/nullp.lis\n@@ ")
    assert b"\xb5" in run.out and b"\r\n" in run.out  # the file's own encoding and line endings
    patch = tmp_path / "p.patch"
    patch.write_bytes(run.out)
    checked = _git("apply", "--check", "p.patch", cwd=tmp_path)
    assert checked.returncode == 0, checked.stderr
    assert _git("apply", "p.patch", cwd=tmp_path).returncode == 0
    fixed = tmp_path / "fixed.lis"
    fixed.write_bytes(CP1252)
    done = ["format"] if command[0] == "format" else ["lint", "--fix"]
    zero_cli(*done, "fixed.lis", cwd=tmp_path)
    assert f.read_bytes() == fixed.read_bytes() != CP1252
    if shutil.which("patch"):
        f.write_bytes(CP1252)
        assert subprocess.run(["patch", "-p1", "--dry-run", "-i", "p.patch"], cwd=tmp_path,
                              capture_output=True, check=False).returncode == 0


def test_a_diff_without_changes_is_empty_and_exits_0(tmp_path: Path) -> None:
    f = tmp_path / "ok.lis"
    f.write_bytes(b"np_grp[1].achse[0].versch                             100\nEnde\n")
    run = zero_cli("lint", "--diff", str(f))
    assert (run.code, run.out) == (0, b"")


# ------------------------------------------------------------------------ standard input


@pytest.mark.parametrize("name", ["bad.nc", "hand.yaml"])
def test_stdin_filename_reads_as_a_file_of_that_name(name: str) -> None:
    path = FIXTURES / ("programs" if name.endswith(".nc") else "diff") / name
    from_file = zero_cli("lint", "--output-format", "concise", str(path))
    from_stdin = zero_cli("lint", "--output-format", "concise", "-", "--stdin-filename", str(path),
                          stdin=path.read_bytes())
    assert (from_stdin.code, from_stdin.out) == (from_file.code, from_file.out)


def test_format_reads_standard_input() -> None:
    path = FIXTURES / "seed" / "nullp_3achsen.lis"
    formatted = zero_cli("format", "-", stdin=path.read_bytes())
    assert formatted.code == 0 and formatted.err == b""
    assert zero_cli("format", "--check", "-", stdin=formatted.out).code == 0
    assert zero_cli("format", "--check", "-", stdin=path.read_bytes().replace(b"  ", b" ")).code == 1


@pytest.mark.parametrize(("name", "text"), [
    ("big.json", '{"a": ' + "7" * 5000 + "}"),
    ("big.toml", "[np_grp]\nx = " + "7" * 5000 + "\n"),
])
def test_a_number_of_any_size_gets_a_located_error(tmp_path: Path, name: str, text: str) -> None:
    f = tmp_path / name
    f.write_text(text)
    for command in (["lint"], ["convert", "--to", "lis"]):
        run = zero_cli(*command, str(f))
        # lint: one S017 finding where the reader stopped (issue 27), convert: a located error
        said = run.stdout if command == ["lint"] else run.stderr
        assert run.code == 1 if command == ["lint"] else run.code in (1, 2)
        assert "a number of 5000 digits: no parameter holds it" in said
        assert f"{f}:" + ("1:7" if name.endswith("json") else "2:5") in said


def test_read_file_refuses_what_is_not_a_regular_file(tmp_path: Path) -> None:
    with pytest.raises(ZeroError, match="is a directory"):
        read_file(tmp_path)
    with pytest.raises(ZeroError, match="no such file"):
        read_file(tmp_path / "missing.lis")


# ------------------------------------------------------------- containment (issue 23)

_WRITER = """
import os, sys, time
from pathlib import Path
import zero.files

def slow_write_all(fd, data):  # a slow disk: the kill lands inside a write, often the in-place copy
    view = memoryview(data)
    while view:
        n = os.write(fd, view[:65536])
        view = view[n:]
        time.sleep(0.0005)

zero.files._write_all = slow_write_all
sys.stdout.write("ready\\n")
sys.stdout.flush()
zero.files.write_atomic(Path(sys.argv[1]), Path(sys.argv[2]).read_bytes(), force=True)
"""


def test_a_hard_linked_file_killed_half_way_is_completed_never_mixed(tmp_path: Path) -> None:
    """README: "so the file is old or new, never a mix". SIGKILL at random moments of an in-place
    rewrite (the file has a second hard link): the next
    zero that reads the file finds it old or new, never mixed, and the complete new text is never
    thrown away (it was: the next run deleted it as a stale temporary file)."""
    import random

    old = b"".join(b"np_grp[%d].achse[0].versch %d\n" % (i % 97, i) for i in range(300_000))  # ~9 MB
    new = old.replace(b"versch", b"versch ").replace(b"achse[0]", b"achse[1]")
    source = tmp_path / "new.bin"
    source.write_bytes(new)
    rng = random.Random(23)
    outcomes = {"old": 0, "new": 0}
    for attempt in range(12):
        target = tmp_path / f"list{attempt}.lis"
        target.write_bytes(old)
        os.link(target, tmp_path / f"other{attempt}.lis")
        child = subprocess.Popen([sys.executable, "-c", _WRITER, str(target), str(source)], stdout=subprocess.PIPE)
        assert child.stdout is not None and child.stdout.readline() == b"ready\n"
        if attempt % 2:  # during the copy: once its journal is there
            deadline = time.monotonic() + 20
            while not any(p.name.endswith(".journal") for p in tmp_path.iterdir()) and time.monotonic() < deadline:
                threading.Event().wait(0.002)
            threading.Event().wait(rng.uniform(0.0, 0.08))
        else:  # at any moment
            threading.Event().wait(rng.uniform(0.05, 0.8))
        child.kill()
        child.wait()
        data = read_file(target)  # this process: the killed writer's journal is completed here
        assert data in (old, new), f"attempt {attempt}: a mixed file of {len(data)} bytes"
        outcomes["old" if data == old else "new"] += 1
        assert (tmp_path / f"other{attempt}.lis").read_bytes() == data  # one inode, both names
        assert not [p for p in tmp_path.iterdir() if p.name.endswith(".journal")]  # completed, then removed
    assert outcomes["new"] >= 1 and outcomes["old"] >= 1, outcomes


def _dead_pid() -> str:
    return subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True,
                          check=True).stdout.strip()


# Every command that reads a list (each may complete a journal), and every one that writes it.
_READERS = [["lint", "{d}"], ["lint", "{f}"], ["show", "{f}"], ["format", "--check", "{f}"], ["diff", "{f}", "{f}"],
            ["convert", "{f}", "--to", "yaml"], ["lint", "--machine", "{f}"], ["format", "{f}"],
            ["lint", "--fix", "{f}"]]


@pytest.mark.skipif(not hasattr(os, "chown") or os.geteuid() != 0, reason="needs root to give a file another owner")
@pytest.mark.parametrize("command", _READERS)
def test_a_planted_journal_never_writes_through_a_link_onto_another_users_file(tmp_path: Path,
                                                                            command: list[str]) -> None:
    """README: "A journal is applied only when it is proven zero's own". Issue 43: `mkdir v p; echo ORIG >v/t;
    chown 1234 v/t; ln -s $PWD/v/t p/x.lis; echo PWNED >p/.x.lis.zero-999999-0.journal; zero lint p` wrote
    PWNED into v/t. A journal planted beside the link, beside the file itself, or forged with a header
    for another file, is never applied, by any command that reads or writes the file."""
    victim = tmp_path / "v" / "t"
    victim.parent.mkdir()
    victim.write_bytes(b"ORIG\n")
    os.chown(victim, 1234, 1234)
    folder = tmp_path / "p"
    folder.mkdir()
    (folder / "x.lis").symlink_to(victim)
    dead = _dead_pid()
    (folder / f".x.lis.zero-{dead}-0.journal").write_bytes(b"PWNED\n")
    (victim.parent / f".t.zero-{dead}-0.journal").write_bytes(b"PWNED\n")
    from zero.files import _journal_bytes  # a well-formed journal for another inode: forged

    other = tmp_path / "other"
    other.write_bytes(b"ORIG\n")
    (victim.parent / f".t.zero-{dead}-1.journal").write_bytes(_journal_bytes(other.stat(), "t", b"ORIG\n",
                                                                             b"PWNED\n"))
    args = [a.format(d=str(folder), f=str(folder / "x.lis")) for a in command]
    run = zero_cli(*args, cwd=tmp_path)
    assert victim.read_bytes() == b"ORIG\n", run
    assert victim.stat().st_uid == 1234
    assert "completed from its journal" not in run.stderr


@pytest.mark.parametrize("command", _READERS)
def test_a_journal_that_is_not_zeros_own_is_left_and_said(tmp_path: Path, command: list[str]) -> None:
    """A file with two hard links (journals are looked for): a journal without zero's header, or one
    written for another file, is not applied; it is left, and said once."""
    target = tmp_path / "a.lis"
    target.write_bytes(LIST)
    os.link(target, tmp_path / "b.lis")
    journal = tmp_path / f".a.lis.zero-{_dead_pid()}-0123abcd.journal"
    journal.write_bytes(b"PWNED\n")
    args = [a.format(d=str(tmp_path), f=str(target)) for a in command]
    run = zero_cli(*args, cwd=tmp_path)
    assert b"PWNED" not in target.read_bytes(), run
    assert journal.read_bytes() == b"PWNED\n"
    assert f"{journal.name} not applied: not a journal zero wrote" in run.stderr, run


def test_a_stale_journal_never_undoes_a_newer_edit_through_the_other_name(tmp_path: Path) -> None:
    """Issue 43: a journal of a killed rewrite of `a.lis`, then an edit through the other hard-link
    name `b.lis`: the next zero replayed the journal and the edit was lost. A journal of zero's own
    for this very file whose old content is no longer there is removed, unapplied."""
    from zero.files import _journal_bytes

    target = tmp_path / "a.lis"
    target.write_bytes(b"np_grp[1].achse[0].versch 1\nEnde\n")
    os.link(target, tmp_path / "b.lis")
    journal = tmp_path / f".a.lis.zero-{_dead_pid()}-0123abcd.journal"
    journal.write_bytes(_journal_bytes(target.stat(), "a.lis", target.read_bytes(), b"np_grp[1].achse[0].versch 2\n"))
    with (tmp_path / "b.lis").open("r+b") as f:  # an edit in place, through the other name
        f.write(b"np_grp[1].achse[0].versch 7\nEnde\n")
    assert read_file(target) == b"np_grp[1].achse[0].versch 7\nEnde\n"
    assert not journal.exists()
    # the same journal over the old content, or over a copy stopped half way, is completed
    for current in (b"np_grp[1].achse[0].versch 1\nEnde\n", b"np_grp[1].achse[0].versch 2\nEnde\n",
                    b"np_grp[1].achse[0].versch 1\nEnde\n\0\0"[:30]):
        target.write_bytes(b"np_grp[1].achse[0].versch 1\nEnde\n")
        journal.write_bytes(_journal_bytes(target.stat(), "a.lis", target.read_bytes(),
                                           b"np_grp[1].achse[0].versch 2\n"))
        with target.open("r+b") as f:
            f.write(current)
        write_atomic(target, b"NEWER\n", force=True)
        assert target.read_bytes() == b"NEWER\n" == (tmp_path / "b.lis").read_bytes()
        assert not journal.exists()


def test_a_signal_never_leaves_a_padded_or_mixed_file(tmp_path: Path) -> None:
    """Issue 43: SIGTERM while the journal appeared left the old text plus 38,050 NUL bytes (3 of 15
    runs) while zero said "nothing was replaced". Now a signal at any moment leaves the old or the new
    content, and what zero says matches what it left."""
    import random

    old = b"np_grp[1].achse[0].versch 1\n" * 2000
    new = old * 20  # longer: its blocks are claimed before the copy
    source = tmp_path / "new.bin"
    source.write_bytes(new)
    rng = random.Random(43)
    seen = set()
    for attempt in range(15):
        target = tmp_path / f"l{attempt}.lis"
        target.write_bytes(old)
        os.link(target, tmp_path / f"o{attempt}.lis")
        child = subprocess.Popen([sys.executable, "-c", _WRITER, str(target), str(source)], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE)
        assert child.stdout is not None and child.stdout.readline() == b"ready\n"
        threading.Event().wait(rng.uniform(0.0, 0.12))
        child.send_signal(signal.SIGTERM)
        _, err = child.communicate(timeout=30)
        data = target.read_bytes()
        assert data in (old, new), f"attempt {attempt}: {len(data)} bytes, {data.count(0)} NUL"
        if b"nothing was replaced" in err:
            assert data == old, attempt
        elif b"written completely" in err or child.returncode == 0:
            assert data == new, attempt
        seen.add(data == new)
        assert not [p for p in tmp_path.iterdir() if ".zero-" in p.name]
    assert seen == {True, False}, seen


@pytest.mark.skipif(not hasattr(os, "chown") or os.geteuid() != 0, reason="needs root to give a file another owner")
@pytest.mark.parametrize("command", [["format", "{f}"], ["lint", "--fix", "{f}"], ["lint", "--add-noqa", "{f}"],
                                     ["convert", "{g}", "--to", "lis", "-o", "{f}", "--force"]])
def test_zero_never_writes_through_a_link_to_another_users_file(tmp_path: Path, command: list[str]) -> None:
    """README: "never through a symbolic link to a file of another user"."""
    victim = tmp_path / "v" / "t.lis"
    victim.parent.mkdir()
    victim.write_bytes(CP1252)
    os.chown(victim, 1234, 1234)
    (tmp_path / "x.lis").symlink_to(victim)
    (tmp_path / "g.yaml").write_text("kind: zero\n")
    args = [a.format(f="x.lis", g="g.yaml") for a in command]
    run = zero_cli(*args, cwd=tmp_path)
    assert victim.read_bytes() == CP1252, run
    assert "belongs to another user" in run.stderr or "not" in run.stderr, run


def test_a_full_disk_leaves_a_hard_linked_file_as_it_was(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """README: "a longer text claims its disk blocks first, so a full disk changes nothing"."""
    import errno

    target = tmp_path / "a.lis"
    target.write_bytes(b"old\n")
    os.link(target, tmp_path / "b.lis")

    def full(fd: int, offset: int, length: int) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "posix_fallocate", full)
    with pytest.raises(ZeroError, match=r"No space left.*the file is unchanged"):
        write_atomic(target, b"a longer new content\n" * 100, force=True)
    assert target.read_bytes() == b"old\n" == (tmp_path / "b.lis").read_bytes()
    # nothing was written, so no journal is left for the next zero to complete: a write the user was
    # told had failed must not happen later (it did: the next `zero lint` applied it)
    assert [p.name for p in tmp_path.iterdir() if ".zero-" in p.name] == []
    assert read_file(target) == b"old\n"


def test_a_file_growing_while_it_is_read_is_refused_without_holding_it(tmp_path: Path) -> None:
    """The size limit bounds memory: a file that grows while it is read is cut off at the limit."""
    path = tmp_path / "grows.lis"
    path.write_bytes(b"a 1\n" * 10)
    stop = threading.Event()

    def grow() -> None:
        with path.open("ab") as f:
            while not stop.is_set():
                f.write(b"a 1\n" * 4096)
                f.flush()

    writer = threading.Thread(target=grow)
    writer.start()
    try:
        for _ in range(20):
            try:
                data = read_file(path, limit=1 << 20)
            except ZeroError as exc:
                assert "larger than" in exc.message
                continue
            assert len(data) <= 1 << 20
    finally:
        stop.set()
        writer.join()


@pytest.mark.parametrize("how", ["symlink", "hardlink", "pyproject", "no-suffix", "symlink-to-config"])
def test_a_report_never_replaces_a_list_or_a_configuration(tmp_path: Path, how: str) -> None:
    """README: "not by its name, not through a symbolic or hard link". `-o` looked at the name only: a
    link named rep.json replaced the list it points to, and
    `-o pyproject.toml` or a list without a suffix was replaced without --force."""
    good = tmp_path / "good.lis"
    good.write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n')
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    target = {"symlink": "rep.json", "hardlink": "rep.json", "pyproject": "pyproject.toml",
              "no-suffix": "hochlauf", "symlink-to-config": "rep.sarif"}[how]
    if how == "symlink":
        (tmp_path / target).symlink_to(good)
    elif how == "hardlink":
        os.link(good, tmp_path / target)
    elif how == "no-suffix":
        (tmp_path / target).write_text("# start-up list\nkanal_anzahl 1\nsda_mds[0] ./kanal.lis\nEnde\n")
        before[target] = (tmp_path / target).read_bytes()
    elif how == "symlink-to-config":
        (tmp_path / target).symlink_to(tmp_path / "pyproject.toml")
    run = zero_cli("lint", "good.lis", "--output-format", "json", "-o", target, cwd=tmp_path)
    assert run.code == 2 and "not replaced" in run.stderr, run
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.name in before} == before


_REPORTERS = {"lint": ["lint", "good.lis", "--output-format", "json", "-o", "{t}"],
              "report": ["report", "--machine", "m/hochlauf.lis", "-o", "{t}", "--force"],
              "schema": ["schema", "-o", "{t}", "--force"]}


@pytest.mark.parametrize("command", sorted(_REPORTERS))
@pytest.mark.parametrize("target", ["m/hochlauf.lis", "header", "form.json", "form.yaml", "pyproject.toml",
                                    "link.json", "comments"])
def test_no_output_ever_replaces_a_list_a_form_or_a_configuration(tmp_path: Path, command: str, target: str) -> None:
    """README: "A report (`lint -o`, `report -o`, `schema -o`) never replaces a list". Issue 43: `-o` replaced
    a suffix-less list that starts with a 9 KB comment header (the sniff read 8 KB), and `zero report -o
    m/hochlauf.lis --force` replaced the machine's own start-up list with HTML. Every command that writes a
    report, every kind of target, with --force: refused, the file unchanged."""
    shutil.copytree(FIXTURES / "machine-clean" / "listen", tmp_path / "m")
    for f in (tmp_path / "m").iterdir():
        f.write_text(f.read_text().replace("./listen/", "./"))
    (tmp_path / "good.lis").write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    (tmp_path / "header").write_text("".join(f"# {i:4d} a comment header of a list, as long as it likes\n"
                                             for i in range(200)) + "np_grp[1].achse[0].versch 5\nEnde\n")
    assert (tmp_path / "header").stat().st_size > 9000
    (tmp_path / "comments").write_text("# nothing but comments\n" * 600)
    zero_cli("convert", "good.lis", "--to", "json", "-o", "form.json", cwd=tmp_path)
    zero_cli("convert", "good.lis", "--to", "yaml", "-o", "form.yaml", cwd=tmp_path)
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n')
    (tmp_path / "link.json").symlink_to(tmp_path / "m" / "hochlauf.lis")
    before = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    run = zero_cli(*(a.format(t=target) for a in _REPORTERS[command]), cwd=tmp_path)
    assert run.code == 2 and "not replaced" in run.stderr, run
    assert {p: p.read_bytes() for p in before} == before


@pytest.mark.parametrize("target", ["pyproject.toml", "zero.toml", "link.toml"])
def test_a_conversion_never_replaces_a_configuration(tmp_path: Path, target: str) -> None:
    (tmp_path / "good.lis").write_text("np_grp[1].achse[0].versch 5\nEnde\n")
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n')
    (tmp_path / "zero.toml").write_text("select = []\n")
    (tmp_path / "link.toml").symlink_to(tmp_path / "pyproject.toml")
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    run = zero_cli("convert", "good.lis", "--to", "toml", "-o", target, "--force", cwd=tmp_path)
    assert run.code == 2 and "configuration file" in run.stderr, run
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


def test_reports_replace_previous_reports_of_every_command(tmp_path: Path) -> None:
    shutil.copytree(FIXTURES / "machine-clean" / "listen", tmp_path / "m")
    for f in (tmp_path / "m").iterdir():
        f.write_text(f.read_text().replace("./listen/", "./"))
    for args in (["report", "--machine", "m/hochlauf.lis", "-o", "r.html"], ["schema", "-o", "s.json"]):
        assert zero_cli(*args, cwd=tmp_path).code == 0
        again = zero_cli(*args, cwd=tmp_path)
        assert again.code == 2 and "already exists" in again.stderr, again
        assert zero_cli(*args, "--force", cwd=tmp_path).code == 0


def test_a_report_replaces_the_previous_report(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_text("np_grp[1].achse[0]. versch 5\nEnde\n")  # S004 (with --strict: exit 1)
    for fmt, name in (("json", "r.json"), ("sarif", "r.sarif"), ("junit", "r.xml"), ("text", "r.txt"),
                      ("concise", "r.txt"), ("github", "r.txt"), ("gitlab", "r.json")):
        for _ in range(2):  # the second run replaces the first report
            run = zero_cli("lint", "a.lis", "--strict", "--output-format", fmt, "-o", name, cwd=tmp_path)
            assert run.code == 1, (fmt, run)
        assert (tmp_path / name).stat().st_size > 0


@pytest.mark.skipif(not Path("/proc/self/status").is_file(), reason="no /proc here")
def test_a_file_that_says_it_has_no_size_is_read_whole() -> None:
    """/proc files (and some FUSE files) say st_size 0: reading stops at the size limit, not at the size."""
    data = read_file("/proc/self/status")
    assert b"Name:" in data and len(data) > 100


@given(st.sampled_from(["x.lis", "a.b", "x.lis.zero-1"]), st.sampled_from(["tmp", "journal"]),
       st.text(alphabet="x.lisabcdef0123456789-zero٣ \n", max_size=30))
def test_a_leftover_is_recognised_as_the_pattern_it_replaced_did(target: str, suffix: str, name: str) -> None:
    """``_leftover_pid`` (start-up: without re) reads a name as ``\\.{target}\\.zero-([0-9]+)-[0-9a-f]+\\.{suffix}``."""
    import re

    from zero.files import _leftover_pid

    for candidate in (name, f".{target}.zero-{name}.{suffix}", f".{target}.zero-{name}"):
        m = re.fullmatch(r"\." + re.escape(target) + r"\.zero-([0-9]+)-[0-9a-f]+\." + suffix, candidate)
        assert _leftover_pid(candidate, f".{target}.zero-", f".{suffix}") == (int(m.group(1)) if m else None)


def test_walk_is_os_walk_without_its_recursion(tmp_path: Path) -> None:
    """zero.files.walk gives what os.walk gives, in its order, with a caller's pruning honoured: links to
    folders listed but not entered, a dangling link a file, an unreadable folder skipped."""
    import os
    import random

    from zero.files import walk

    rng = random.Random(4)
    folders = [tmp_path / "t"]
    folders[0].mkdir()
    for n in range(60):
        parent = rng.choice(folders)
        if rng.random() < 0.5:
            child = parent / f"d{n}"
            child.mkdir()
            folders.append(child)
        else:
            (parent / f"f{n}.lis").write_text("x\n")
    (folders[3] / "to_top").symlink_to(tmp_path / "t")
    (folders[4] / "dangling").symlink_to(tmp_path / "nowhere")
    locked = folders[5] / "locked"
    locked.mkdir()
    (locked / "inside.lis").write_text("x\n")
    locked.chmod(0)
    try:
        def listed(walker: Iterator[tuple[str, list[str], list[str]]], prune: bool
                   ) -> list[tuple[str, list[str], list[str]]]:
            out = []
            for root, dirs, files in walker:
                dirs.sort()
                if prune:
                    dirs[:] = [d for d in dirs if not d.endswith("3")]
                out.append((root, list(dirs), sorted(files)))
            return out

        for prune in (False, True):
            assert listed(walk(str(tmp_path / "t")), prune) == listed(os.walk(str(tmp_path / "t")), prune)
    finally:
        locked.chmod(0o755)
