-- zero's language server in Neovim 0.7 and later, restarted when it dies.
--
-- Put this file on the runtime path as lua/zero.lua (e.g. ~/.config/nvim/lua/zero.lua) and add
--
--   require("zero").setup()                                   -- or, with options:
--   require("zero").setup({ cmd = { "/path/to/.venv/bin/zero", "server" }, init_options = { debounce = 250 } })
--
-- to init.lua. Every list (*.lis, *.lst) and NC program (*.nc, *.mpf, *.spf) opened is attached to one
-- server per project root (the nearest directory with pyproject.toml, zero.toml, .zero.toml or .git).
-- When a server dies (killed, crashed) a new one is started for its root and every buffer it had is
-- attached again, so that findings come back without restarting Neovim; at most `max_restarts` times a
-- minute, after which a message says so. :ZeroRestart restarts by hand, :ZeroStop stops for good.
-- Neovim 0.8 and later use vim.lsp.start, 0.7 (Debian bookworm) vim.lsp.start_client with
-- vim.lsp.buf_attach_client. tests/server/test_nvim.py loads this file as it is.
--
-- Completion: the built-in omnifunc works as it is (`:setlocal omnifunc=v:lua.vim.lsp.omnifunc`, set
-- below for the buffers attached, then <C-x><C-o> mid-key: `np_grp[1].achse[0].ve` completes to
-- `np_grp[1].achse[0].versch`); so does nvim-cmp with its nvim_lsp source.
local M = {}

local defaults = {
  cmd = { "zero", "server" },
  patterns = { "*.lis", "*.lst", "*.nc", "*.mpf", "*.spf" },
  markers = { "pyproject.toml", "zero.toml", ".zero.toml", ".git" },
  init_options = nil, -- server settings, e.g. { debounce = 250, ruleDocs = "…" }
  max_restarts = 5, -- restarts of one root's server within a minute before giving up
  omnifunc = true, -- set omnifunc to vim.lsp.omnifunc in the buffers attached
}

local config = vim.deepcopy(defaults)
local clients = {} -- root directory -> client id
local attached = {} -- buffer number -> root directory
local restarts = {} -- root directory -> times (ms) of recent restarts
local stopping = false -- set when Neovim exits or :ZeroStop is used

local function notify(message, level)
  vim.notify("zero: " .. message, level or vim.log.levels.INFO)
end

--- The project root of a buffer: the directory of the nearest marker above its file, else its directory.
function M.root_of(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  local dir = name ~= "" and vim.fn.fnamemodify(name, ":p:h") or vim.fn.getcwd()
  local best
  for _, marker in ipairs(config.markers) do
    local found = vim.fn.findfile(marker, dir .. ";")
    if found == "" then
      found = vim.fn.finddir(marker, dir .. ";")
    end
    if found ~= "" then
      local path = (vim.fn.fnamemodify(found, ":p"):gsub("/$", ""))
      local root = vim.fn.fnamemodify(path, ":h")
      if best == nil or #root > #best then
        best = root
      end
    end
  end
  return best or dir
end

local on_exit

local function client_config(root)
  return {
    name = "zero",
    cmd = config.cmd,
    root_dir = root,
    init_options = config.init_options,
    on_exit = function(code, signal, client_id)
      vim.schedule(function()
        on_exit(root, client_id, code, signal)
      end)
    end,
  }
end

local function attach_to(bufnr, root)
  if vim.lsp.start then -- Neovim 0.8 and later: one client per name and root, reused
    local id
    vim.api.nvim_buf_call(bufnr, function()
      id = vim.lsp.start(client_config(root))
    end)
    return id
  end
  local id = clients[root] -- Neovim 0.7
  if id == nil or vim.lsp.get_client_by_id(id) == nil then
    id = vim.lsp.start_client(client_config(root))
  end
  if id ~= nil then
    vim.lsp.buf_attach_client(bufnr, id)
  end
  return id
end

--- Attach a buffer (the current one by default) to the server of its root, starting it if need be.
function M.attach(bufnr)
  if bufnr == nil or bufnr == 0 then
    bufnr = vim.api.nvim_get_current_buf()
  end
  stopping = false
  local root = M.root_of(bufnr)
  local id = attach_to(bufnr, root)
  if id == nil then
    notify("could not start " .. table.concat(config.cmd, " "), vim.log.levels.ERROR)
    return nil
  end
  clients[root] = id
  attached[bufnr] = root
  if config.omnifunc then
    vim.api.nvim_buf_set_option(bufnr, "omnifunc", "v:lua.vim.lsp.omnifunc")
  end
  return id
end

local function reattach(root)
  for bufnr, r in pairs(attached) do
    if r == root then
      if vim.api.nvim_buf_is_loaded(bufnr) then
        M.attach(bufnr)
      else
        attached[bufnr] = nil
      end
    end
  end
end

on_exit = function(root, client_id, code, signal)
  if clients[root] ~= client_id then
    return -- a server replaced already
  end
  clients[root] = nil
  if stopping or vim.v.exiting ~= vim.NIL or (code == 0 and signal == 0) then
    return -- asked to stop: zero's server exits with 0 only after a shutdown request
  end
  local now = vim.loop.now()
  local recent = {}
  for _, t in ipairs(restarts[root] or {}) do
    if now - t < 60000 then
      table.insert(recent, t)
    end
  end
  if #recent >= config.max_restarts then
    restarts[root] = recent
    notify(string.format("the server for %s stopped %d times within a minute; not restarted (:ZeroRestart)",
      root, #recent), vim.log.levels.ERROR)
    return
  end
  table.insert(recent, now)
  restarts[root] = recent
  notify(string.format("the server for %s stopped (exit code %s, signal %s); restarting", root, code, signal),
    vim.log.levels.WARN)
  reattach(root)
end

--- Stop every server of zero (not restarted).
function M.stop()
  stopping = true
  for root, id in pairs(clients) do
    clients[root] = nil
    vim.lsp.stop_client(id)
  end
end

--- Stop the servers and attach their buffers to new ones.
function M.restart()
  local roots = {}
  for _, root in pairs(attached) do
    roots[root] = true
  end
  M.stop()
  restarts = {}
  vim.defer_fn(function()
    stopping = false
    for root in pairs(roots) do
      reattach(root)
    end
  end, 500)
end

function M.setup(opts)
  config = vim.tbl_deep_extend("force", vim.deepcopy(defaults), opts or {})
  local group = vim.api.nvim_create_augroup("zero", { clear = true })
  vim.api.nvim_create_autocmd({ "BufReadPost", "BufNewFile" }, {
    group = group,
    pattern = config.patterns,
    callback = function(args)
      M.attach(args.buf)
    end,
  })
  vim.api.nvim_create_autocmd({ "BufUnload" }, {
    group = group,
    callback = function(args)
      attached[args.buf] = nil
    end,
  })
  vim.api.nvim_create_autocmd({ "VimLeavePre" }, {
    group = group,
    callback = function()
      stopping = true
    end,
  })
  vim.api.nvim_create_user_command("ZeroRestart", M.restart, { desc = "Restart zero's language server" })
  vim.api.nvim_create_user_command("ZeroStop", M.stop, { desc = "Stop zero's language server" })
  -- the buffers open already (setup called after a list was opened, e.g. `nvim -c 'lua …' list.lis`)
  for _, bufnr in ipairs(vim.api.nvim_list_bufs()) do
    local name = vim.api.nvim_buf_get_name(bufnr)
    if vim.api.nvim_buf_is_loaded(bufnr) and name ~= "" and attached[bufnr] == nil then
      for _, pattern in ipairs(config.patterns) do
        if vim.fn.match(name, vim.fn.glob2regpat(pattern)) >= 0 then
          M.attach(bufnr)
          break
        end
      end
    end
  end
  return M
end

--- With nvim-lspconfig (Neovim 0.8 and later) instead of setup(): lspconfig starts the server for the
--- file types `isglist` and `isgnc` (defined here) and this restarts it the same way when it dies.
function M.lspconfig(opts)
  opts = opts or {}
  local lspconfig = require("lspconfig")
  local configs = require("lspconfig.configs")
  local util = require("lspconfig.util")
  vim.filetype.add({ extension = { lis = "isglist", lst = "isglist", nc = "isgnc", mpf = "isgnc", spf = "isgnc" } })
  if not configs.zero then
    configs.zero = {
      default_config = {
        cmd = opts.cmd or defaults.cmd,
        filetypes = { "isglist", "isgnc" },
        root_dir = util.root_pattern(unpack(defaults.markers)),
        init_options = opts.init_options,
      },
    }
  end
  local count = 0
  lspconfig.zero.setup({
    on_exit = function(code, signal)
      if code == 0 and signal == 0 then
        return
      end
      vim.schedule(function()
        if vim.v.exiting ~= vim.NIL or count >= defaults.max_restarts then
          return
        end
        count = count + 1
        notify("the server stopped; restarting", vim.log.levels.WARN)
        vim.cmd("LspStart zero") -- lspconfig attaches the open buffers of zero's file types again
      end)
    end,
  })
end

return M
