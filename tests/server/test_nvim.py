"""End to end in a real editor: headless Neovim attaches ``zero server`` to a faulty list, waits for
the findings and writes what it shows; they are ``zero lint``'s, line for line.

Neovim comes from the system packages (Debian bookworm ships 0.7, which has ``vim.lsp.start_client``
but not yet ``vim.lsp.start``; the Lua below uses whichever there is). Skipped, with the reason, where
``nvim`` is not installed or too old for ``vim.diagnostic`` (0.6).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli

pytestmark = pytest.mark.slow

LUA = r"""
local out = os.getenv("ZERO_NVIM_OUT")
local cmd = { os.getenv("ZERO_NVIM_PYTHON"), "-m", "zero", "server" }
local function finish(status, lines)
  local f = assert(io.open(out, "w"))
  f:write(status .. "\n" .. table.concat(lines, "\n") .. "\n")
  f:close()
  vim.cmd("qall!")
end
vim.defer_fn(function() finish("killed", {}) end, 60000)  -- never hang the test run
local bufnr = vim.api.nvim_get_current_buf()
local root = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(bufnr), ":p:h")
local id
if vim.lsp.start then  -- Neovim 0.8 and later
  id = vim.lsp.start({ name = "zero", cmd = cmd, root_dir = root })
else  -- Neovim 0.7
  id = vim.lsp.start_client({ name = "zero", cmd = cmd, root_dir = root })
  vim.lsp.buf_attach_client(bufnr, id)
end
local ok = vim.wait(45000, function() return #vim.diagnostic.get(bufnr) > 0 end, 50)
local lines = {}
for _, d in ipairs(vim.diagnostic.get(bufnr)) do
  local lsp = d.user_data and d.user_data.lsp or {}
  local code = d.code or lsp.code or "-"
  table.insert(lines, string.format("%d:%d:%s:%s", d.lnum + 1, d.col + 1, tostring(code), d.source or "-"))
end
table.sort(lines)
vim.lsp.stop_client(id)
finish(ok and "ok" or "timeout", lines)
"""


def nvim_version() -> tuple[int, int] | None:
    exe = shutil.which("nvim")
    if exe is None:
        return None
    out = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=30, check=False).stdout
    m = re.search(r"NVIM v(\d+)\.(\d+)", out)
    return (int(m.group(1)), int(m.group(2))) if m else None


def test_neovim_shows_the_findings_of_a_faulty_list(tmp_path: Path) -> None:
    version = nvim_version()
    if version is None:
        pytest.skip("nvim is not on PATH (apt-get install neovim)")
    if version < (0, 6):
        pytest.skip(f"nvim {version[0]}.{version[1]} has no vim.diagnostic (0.6 or later needed)")
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    lua = tmp_path / "attach.lua"
    lua.write_text(LUA, encoding="utf-8")
    out = tmp_path / "diagnostics.txt"
    env = {**os.environ, "ZERO_NVIM_OUT": str(out), "ZERO_NVIM_PYTHON": sys.executable,
           "XDG_CACHE_HOME": str(tmp_path / "cache"), "XDG_STATE_HOME": str(tmp_path / "state"),
           "XDG_DATA_HOME": str(tmp_path / "data")}
    proc = subprocess.run(["nvim", "--headless", "--clean", "-n", "-c", f"luafile {lua}", str(path)],
                          cwd=tmp_path, env=env, capture_output=True, timeout=120, check=False)
    assert out.is_file(), proc.stderr.decode("utf-8", "replace")
    status, *shown = out.read_text(encoding="utf-8").splitlines()
    assert status == "ok", (status, proc.stderr)
    expected = json.loads(zero_cli("lint", "--output-format", "json", path.name, cwd=tmp_path).stdout)
    want = sorted(f"{f['line']}:{f['column']}:{f['code']}:zero" for f in expected)
    assert sorted(shown) == want
    assert {line.split(":")[2] for line in shown} >= {"S004", "M003"}
