"""End to end in a real editor: headless Neovim attaches ``zero server`` to a faulty list, waits for
the findings and writes what it shows; they are ``zero lint``'s, line for line. Then, with the set-up
the documentation points at (``editors/nvim/zero.lua``, loaded as it is): the built-in omnifunc
completes mid-key without doubling the key, and a killed server is restarted by the set-up, its
findings back after the next edit.

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

from conftest import FIXTURES, ROOT, zero_cli

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


def need_nvim(minimum: tuple[int, int], why: str) -> None:
    """Skip, with the reason, where Neovim is missing or older than ``minimum``."""
    version = nvim_version()
    if version is None:
        pytest.skip("nvim is not on PATH (apt-get install neovim)")
    if version < minimum:
        pytest.skip(f"nvim {version[0]}.{version[1]}: {why}")


def test_neovim_shows_the_findings_of_a_faulty_list(tmp_path: Path) -> None:
    need_nvim((0, 6), "has no vim.diagnostic (0.6 or later needed)")
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


# The set-up of editors/nvim/zero.lua, driven step by step: typed keys are handled by Neovim's main
# loop, so the steps run in a coroutine resumed by timers, not in one blocking script.
DRIVER = r"""
local out = assert(io.open(os.getenv("ZERO_NVIM_OUT"), "w"))
local function say(line) out:write(line .. "\n"); out:flush() end
local function finish() out:close(); vim.cmd("qall!") end
vim.defer_fn(function() say("killed: took too long"); finish() end, 100000)  -- never hang the test run
vim.o.completeopt = "menuone,noselect"
local zero = dofile(os.getenv("ZERO_NVIM_SETUP"))
zero.setup({ cmd = { os.getenv("ZERO_NVIM_PYTHON"), "-m", "zero", "server" }, init_options = { debounce = 20 } })
local bufnr = vim.api.nvim_get_current_buf()
local co
local function resume()
  local ok, err = coroutine.resume(co)
  if not ok then say("error: " .. tostring(err)); finish() end
end
local function sleep(ms) vim.defer_fn(resume, ms); coroutine.yield() end
local function wait_until(pred, ms)
  local waited = 0
  while not pred() do
    if waited >= ms then return false end
    sleep(50); waited = waited + 50
  end
  return true
end
local function feed(keys)
  vim.api.nvim_feedkeys(vim.api.nvim_replace_termcodes(keys, true, false, true), "nt", false)
end
local function codes()
  local found = {}
  for _, d in ipairs(vim.diagnostic.get(bufnr)) do
    local lsp = d.user_data and d.user_data.lsp or {}
    table.insert(found, tostring(d.code or lsp.code or "-"))
  end
  table.sort(found)
  return table.concat(found, ",")
end
local function zero_client()
  for _, client in pairs(vim.lsp.buf_get_clients(bufnr)) do
    if client.name == "zero" then return client end
  end
end
-- Type `typed` on a new last line, ask the omnifunc (<C-x><C-o>), take the first item, leave insert mode.
local function complete(typed)
  local last = vim.api.nvim_buf_line_count(bufnr)
  vim.api.nvim_buf_set_lines(bufnr, last, last, false, { "" })
  vim.api.nvim_win_set_cursor(0, { last + 1, 0 })
  feed("A" .. typed .. "<C-x><C-o>")
  local shown = wait_until(function() return #vim.fn.complete_info({ "items" }).items > 0 end, 10000)
  local words = {}
  for _, item in ipairs(vim.fn.complete_info({ "items" }).items) do table.insert(words, item.word) end
  feed(shown and "<C-n><C-y><Esc>" or "<Esc>")
  wait_until(function() return vim.fn.mode() == "n" end, 5000)
  local line = vim.api.nvim_buf_get_lines(bufnr, last, last + 1, false)[1]
  vim.api.nvim_buf_set_lines(bufnr, last, last + 1, false, {})
  say("complete " .. typed .. " -> " .. line .. " | " .. table.concat(words, " "))
end
co = coroutine.create(function()
  if not wait_until(function() return #vim.diagnostic.get(bufnr) > 0 end, 45000) then
    say("error: no findings"); return finish()
  end
  say("findings " .. codes())
  if os.getenv("ZERO_NVIM_STEP") == "complete" then
    for typed in (os.getenv("ZERO_NVIM_TYPED") .. "\n"):gmatch("([^\n]*)\n") do complete(typed) end
  else  -- kill the server: the set-up starts a new one, whose findings come after an edit
    local client = zero_client()
    local pid = client.rpc.pid
    vim.loop.kill(pid, "sigkill")
    local gone = wait_until(function()
      local now = zero_client()
      return now ~= nil and now.id ~= client.id and now.initialized
    end, 30000)
    say("restarted " .. tostring(gone) .. " " .. tostring(zero_client() and zero_client().rpc.pid ~= pid))
    vim.diagnostic.reset(nil, bufnr)
    vim.api.nvim_buf_set_lines(bufnr, 0, 0, false, { "# edited after the restart" })
    wait_until(function() return #vim.diagnostic.get(bufnr) > 0 end, 30000)
    say("findings " .. codes())
    local second = vim.fn.tempname() .. ".lis"
    vim.fn.writefile({ "g53_verfuegbar 7" }, second)
    vim.cmd("edit " .. second)  -- a list opened after the restart is attached too
    local other = vim.api.nvim_get_current_buf()
    wait_until(function() return #vim.diagnostic.get(other) > 0 end, 30000)
    local clients = vim.tbl_count(vim.lsp.buf_get_clients(other))
    say("opened " .. tostring(clients) .. " " .. tostring(#vim.diagnostic.get(other) > 0))
  end
  finish()
end)
resume()
"""

SETUP = ROOT / "editors" / "nvim" / "zero.lua"


def drive_nvim(tmp_path: Path, step: str, typed: list[str] | None = None) -> list[str]:
    """What the driver says for a faulty copy of the zero-offset list, opened in headless Neovim."""
    need_nvim((0, 7), "the set-up needs 0.7 (nvim_create_autocmd)")
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    lua = tmp_path / "driver.lua"
    lua.write_text(DRIVER, encoding="utf-8")
    out = tmp_path / "driver.txt"
    env = {**os.environ, "ZERO_NVIM_OUT": str(out), "ZERO_NVIM_PYTHON": sys.executable,
           "ZERO_NVIM_SETUP": str(SETUP), "ZERO_NVIM_STEP": step, "ZERO_NVIM_TYPED": "\n".join(typed or []),
           "XDG_CACHE_HOME": str(tmp_path / "cache"), "XDG_STATE_HOME": str(tmp_path / "state"),
           "XDG_DATA_HOME": str(tmp_path / "data")}
    proc = subprocess.run(["nvim", "--headless", "--clean", "-n", "-c", f"luafile {lua}", str(path)],
                          cwd=tmp_path, env=env, capture_output=True, timeout=150, check=False)
    assert out.is_file(), proc.stderr.decode("utf-8", "replace")
    said = out.read_text(encoding="utf-8").splitlines()
    assert not any(line.startswith(("error", "killed")) for line in said), (said, proc.stderr)
    return said


def test_neovim_omnifunc_completes_mid_key_without_doubling(tmp_path: Path) -> None:
    typed = ["np_grp[1].achse[0].ve", "np_grp[1].achse[0].", "np_grp[1].ach", "np_gr", "kenngr.sw"]
    said = drive_nvim(tmp_path, "complete", typed)
    done = {line.split(" -> ")[0].removeprefix("complete "): line.split(" -> ")[1] for line in said
            if line.startswith("complete ")}
    assert done["np_grp[1].achse[0].ve"] == "np_grp[1].achse[0].versch | versch"
    # nothing typed after the dot: both members of the axis, the first of them taken
    assert done["np_grp[1].achse[0]."] == "np_grp[1].achse[0].inaktiv | inaktiv versch"
    line, words = done["np_grp[1].ach"].split(" | ")  # the next axis not set in group 1
    assert re.fullmatch(r"np_grp\[1\]\.achse\[\d+\]\.inaktiv", line), line
    assert words.split() and all(w.startswith("achse[") for w in words.split())
    line, words = done["np_gr"].split(" | ")  # one word so far: the whole key
    assert re.fullmatch(r"np_grp\[\d+\]\.achse\[\d+\]\.inaktiv", line), line
    assert done["kenngr.sw"] == "kenngr.sw | "  # an axis key: none in a zero-offset list


def test_neovim_setup_restarts_a_killed_server(tmp_path: Path) -> None:
    said = drive_nvim(tmp_path, "restart")
    before, restarted, after, opened = said
    assert restarted == "restarted true true"
    assert after == before and {"S004", "M003"} <= set(before.removeprefix("findings ").split(","))
    assert opened == "opened 1 true"
