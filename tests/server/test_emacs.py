"""End to end in Emacs with eglot, set up by ``editors/emacs/zero.el`` as it is (the file the
documentation points at): a faulty list opened in batch Emacs shows zero's findings in flymake,
``completion-at-point`` completes mid-key without doubling the key, and a killed server is reconnected
by eglot itself, its findings back after the next edit.

Emacs runs as in a terminal (``emacs -nw`` on a pseudo-terminal made by ``script``), not in batch: in
batch Emacs 28 never runs the sentinel of a killed server, so eglot could not notice. The driver below
is a chain of timers, the command loop running between its steps as between two keys. Emacs 29 has
eglot built in; Emacs 28 (Debian bookworm) takes it from ``elpa-eglot``. Skipped, with the reason,
where ``emacs`` or ``script`` is not installed or eglot cannot be loaded.
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT, zero_cli

pytestmark = pytest.mark.slow

SETUP = ROOT / "editors" / "emacs" / "zero.el"

DRIVER = r""";; -*- lexical-binding: t -*-
(defvar zero-test-out (getenv "ZERO_EMACS_OUT"))
(defvar zero-test-buffer nil)
(defvar zero-test-server nil)
(defvar zero-test-connected nil)
(defun zero-test-say (fmt &rest args)
  (with-temp-buffer
    (insert (apply #'format fmt args) "\n")
    (append-to-file (point-min) (point-max) zero-test-out)))
(defun zero-test-then (pred seconds next)
  "Call NEXT with PRED's value once it is non-nil (polled on a timer), or with nil after SECONDS."
  (let ((end (+ (float-time) seconds)))
    (cl-labels ((poll ()
                  (let ((value (condition-case err (with-current-buffer zero-test-buffer (funcall pred))
                                 (error (zero-test-say "error: %S" err) (kill-emacs 1)))))
                    (if (or value (> (float-time) end))
                        (condition-case err (with-current-buffer zero-test-buffer (funcall next value))
                          (error (zero-test-say "error: %S" err) (kill-emacs 1)))
                      (run-with-timer 0.1 nil #'poll)))))
      (run-with-timer 0.1 nil #'poll))))
(defun zero-test-codes ()
  (mapconcat #'identity
             (sort (mapcar (lambda (d)
                             (format "%s" (plist-get (alist-get 'eglot-lsp-diag (flymake-diagnostic-data d)) :code)))
                           (flymake-diagnostics))
                   #'string<)
             ","))
(defun zero-test-findings (next)
  "Call NEXT with the codes flymake shows once the server has published findings."
  (zero-test-then (lambda () (and (eglot-current-server) eglot--diagnostics)) 45
                  (lambda (found)
                    (if (not found) (funcall next "none")
                      (flymake-start)
                      (zero-test-then #'flymake-diagnostics 10 (lambda (_) (funcall next (zero-test-codes))))))))
(require 'cl-lib)
(defun zero-test-complete (typed)
  (goto-char (point-max))
  (insert "\n" typed)
  ;; what C-M-i (`completion-at-point') does with eglot's answer, kept for the candidates written out.
  ;; eglot asks with `:cancel-on-input': jsonrpc waits in `sit-for', which gives up (the answer is
  ;; then empty) as soon as any input arrives, and under `script' the terminal's own replies to
  ;; Emacs's queries arrive as input at random moments (a third of the runs came back empty). A user
  ;; pressing nothing gets the answer: wait for it without taking that input as a key.
  (cl-letf (((symbol-function 'sit-for) (lambda (seconds &optional _nodisp) (sleep-for seconds) t)))
    (let* ((capf (eglot-completion-at-point))
           (candidates (all-completions (buffer-substring-no-properties (nth 0 capf) (nth 1 capf))
                                        (nth 2 capf))))
      (let ((completion-extra-properties (nthcdr 3 capf)) (inhibit-message t))
        (completion-in-region (nth 0 capf) (nth 1 capf) (nth 2 capf)))
    (zero-test-say "complete %s -> %s | %s" typed
                   (buffer-substring-no-properties (line-beginning-position) (line-end-position))
                   (mapconcat #'identity candidates " "))))
  (delete-region (1- (line-beginning-position)) (line-end-position)))
(defun zero-test-restart ()
  "Kill the server once it has run longer than `eglot-autoreconnect' asks: eglot reconnects."
  (let ((pid (process-id (jsonrpc--process zero-test-server))))
    (signal-process pid 'SIGKILL)
    (zero-test-then (lambda () (let ((now (eglot-current-server)))
                                 (and now (not (eq now zero-test-server)) (eglot--capabilities now))))
                    60
                    (lambda (restarted)
                      (zero-test-say "restarted %s" (and restarted t))
                      (setq eglot--diagnostics nil)
                      (goto-char (point-min))
                      (insert "# edited after the restart\n")
                      (zero-test-findings (lambda (codes) (zero-test-say "findings %s" codes) (kill-emacs 0)))))))
(setq zero-command (list (getenv "ZERO_EMACS_PYTHON") "-m" "zero" "server")
      zero-initialization-options '(:debounce 20))
(run-with-timer 240 nil (lambda () (zero-test-say "killed: took too long") (kill-emacs 1)))
(add-hook 'emacs-startup-hook
          (lambda ()
            (find-file (getenv "ZERO_EMACS_FILE"))
            (setq zero-test-buffer (current-buffer))
            (zero-test-say "mode %s eglot %s" major-mode (file-name-directory (locate-library "eglot")))
            (run-hooks 'post-command-hook)  ; eglot-ensure connects after the command that opened the file
            (zero-test-findings
             (lambda (codes)
               (zero-test-say "findings %s" codes)
               (setq zero-test-server (eglot-current-server) zero-test-connected (float-time))
               (dolist (typed (split-string (getenv "ZERO_EMACS_TYPED") "\n" t)) (zero-test-complete typed))
               (run-with-timer (max 0 (- (1+ (if (numberp eglot-autoreconnect) eglot-autoreconnect 0))
                                         (- (float-time) zero-test-connected)))
                               nil (lambda () (with-current-buffer zero-test-buffer (zero-test-restart))))))))
"""


def emacs_version() -> tuple[int, int] | None:
    exe = shutil.which("emacs")
    if exe is None:
        return None
    out = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=30, check=False).stdout
    m = re.search(r"GNU Emacs (\d+)\.(\d+)", out)
    return (int(m.group(1)), int(m.group(2))) if m else None


def emacs_env(tmp_path: Path) -> dict[str, str]:
    home = tmp_path / "home"  # no user's init files
    home.mkdir(exist_ok=True)
    return {**os.environ, "HOME": str(home), "XDG_CACHE_HOME": str(tmp_path / "cache"),
            "XDG_CONFIG_HOME": str(tmp_path / "config")}


def eglot_missing(tmp_path: Path) -> str | None:
    """Why eglot cannot be used here, or None."""
    version = emacs_version()
    if version is None:
        return "emacs is not on PATH (apt-get install emacs-nox)"
    probe = subprocess.run(["emacs", "--batch", "-q", "--eval", "(require 'eglot)"], env=emacs_env(tmp_path),
                           capture_output=True, text=True, timeout=60, check=False)
    if probe.returncode != 0:
        return (f"Emacs {version[0]}.{version[1]} has no eglot (built in from Emacs 29; for 28: "
                f"apt-get install elpa-eglot): {probe.stderr.strip().splitlines()[-1:]}")
    return None


# Open a list, say the code page Emacs read it in and the findings flymake shows, and end.
CODEPAGE_DRIVER = DRIVER[:DRIVER.index("(setq zero-command")] + r"""
(setq zero-command (list (getenv "ZERO_EMACS_PYTHON") "-m" "zero" "server")
      zero-initialization-options '(:debounce 20))
(run-with-timer 180 nil (lambda () (zero-test-say "killed: took too long") (kill-emacs 1)))
(add-hook 'emacs-startup-hook
          (lambda ()
            (find-file (getenv "ZERO_EMACS_FILE"))
            (setq zero-test-buffer (current-buffer))
            (zero-test-say "mode %s coding %s" major-mode buffer-file-coding-system)
            (run-hooks 'post-command-hook)
            (zero-test-findings (lambda (codes) (zero-test-say "findings %s" codes) (kill-emacs 0)))))
"""


def drive_emacs(tmp_path: Path, typed: list[str], source: Path = FIXTURES / "seed" / "nullp_3achsen.lis",
                driver_text: str = DRIVER) -> list[str]:
    reason = eglot_missing(tmp_path)
    if reason is not None:
        pytest.skip(reason)
    if shutil.which("script") is None:
        pytest.skip("script (util-linux) is not on PATH: it gives Emacs its terminal")
    path = tmp_path / "nullp.lis"
    shutil.copy(source, path)
    driver = tmp_path / "driver.el"
    driver.write_text(driver_text, encoding="utf-8")
    out = tmp_path / "driver.txt"
    env = {**emacs_env(tmp_path), "ZERO_EMACS_OUT": str(out), "ZERO_EMACS_PYTHON": sys.executable,
           "ZERO_EMACS_FILE": str(path), "ZERO_EMACS_TYPED": "\n".join(typed), "TERM": "xterm"}
    # -q, not -Q: the site start-up files put Debian's ELPA packages (elpa-eglot) on the load path
    command = f"emacs -nw -q -l {shlex.quote(str(SETUP))} -l {shlex.quote(str(driver))}"
    log = tmp_path / "script.log"
    with log.open("wb") as err, subprocess.Popen(["script", "-qec", command, "/dev/null"], cwd=tmp_path, env=env,
                                                 stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=err) as proc:
        try:
            proc.wait(timeout=300)  # stdin stays open (no keys typed) until Emacs exits
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    stderr = log.read_bytes()
    assert out.is_file(), stderr.decode("utf-8", "replace")
    said = out.read_text(encoding="utf-8").splitlines()
    assert not any(line.startswith(("error", "killed")) for line in said), said
    return said


def test_emacs_eglot_findings_completion_and_reconnect(tmp_path: Path) -> None:
    typed = ["np_grp[1].achse[0].ve", "np_grp[1].achse[0].", "np_grp[1].ach"]
    mode, before, *completed, restarted, after = drive_emacs(tmp_path, typed)
    assert mode.startswith("mode zero-list-mode ")
    expected = zero_cli("lint", "--output-format", "json", "nullp.lis", cwd=tmp_path).stdout
    codes = sorted(re.findall(r'"code": "([A-Z][0-9]+)"', expected))
    assert before == "findings " + ",".join(codes) and {"S004", "M003"} <= set(codes)
    done = dict(line.removeprefix("complete ").split(" -> ") for line in completed)
    # mid-key: the one member left is inserted, the key not doubled
    assert done["np_grp[1].achse[0].ve"] == "np_grp[1].achse[0].versch | versch"
    # after the dot: both members offered, nothing to insert but what they share
    assert done["np_grp[1].achse[0]."] == "np_grp[1].achse[0]. | inaktiv versch"
    line, candidates = done["np_grp[1].ach"].split(" | ")
    assert re.fullmatch(r"np_grp\[1\]\.achse\[\d+\]\.", line), done  # the common part of the two
    assert all(c.startswith("achse[") for c in candidates.split()) and len(candidates.split()) == 2
    assert restarted == "restarted t"
    assert after == before


@pytest.mark.parametrize(("text", "coding"), [
    ((FIXTURES / "codepage" / "cp850_comments.lis").read_bytes(), "iso-latin-1-unix"),  # bytes cp1252 lacks
    ("# Grüße, Maß\nkenngr.swe_pos 1500.5\nEnde\n".encode("cp1252"), "windows-1252-unix"),
    ("# Grüße\nkenngr.swe_pos 1500.5\nEnde\n".encode(), "utf-8-unix"),
])
def test_emacs_opens_a_list_in_the_code_page_zero_reads_it_in(tmp_path: Path, text: bytes, coding: str) -> None:
    """A list in CP850 (or another code page that is not UTF-8) once opened as `raw-text` or
    `japanese-shift-jis`: eglot could not send its text and flymake showed nothing (issue 35)."""
    source = tmp_path / "source.lis"
    source.write_bytes(text)
    mode, findings = drive_emacs(tmp_path, [], source, CODEPAGE_DRIVER)
    assert mode == f"mode zero-list-mode coding {coding}"
    expected = zero_cli("lint", "--output-format", "json", "nullp.lis", cwd=tmp_path).stdout
    codes = sorted(re.findall(r'"code": "([A-Z][0-9]+)"', expected))
    assert codes and findings == "findings " + ",".join(codes)
