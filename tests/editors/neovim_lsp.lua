-- Neovim's built-in LSP client against `shaderport lsp`: open a ShaderToy file, wait
-- for the diagnostics, apply the quick fix of the first one, write the buffer.
--   SHADERPORT=BIN nvim --headless -u NONE -c 'luafile neovim_lsp.lua' toy.glsl
-- Writes RESULT (the buffer after the fix) next to the file, or FAIL: ... and exits 1.
local binary = os.getenv('SHADERPORT')
local buf = vim.api.nvim_get_current_buf()
local path = vim.api.nvim_buf_get_name(buf)
local function fail(message)
  io.stderr:write('FAIL: ' .. message .. '\n')
  vim.cmd('cquit 1')
end

local client = vim.lsp.start_client({
  name = 'shaderport',
  cmd = { binary, 'lsp' },
  root_dir = vim.fn.fnamemodify(path, ':h'),
})
if not client then fail('the client did not start') end
vim.lsp.buf_attach_client(buf, client)

local ok = vim.wait(20000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
if not ok then fail('no diagnostics arrived') end
local diagnostics = vim.diagnostic.get(buf)
table.sort(diagnostics, function(a, b) return a.lnum < b.lnum or (a.lnum == b.lnum and a.col < b.col) end)
local first = diagnostics[1]
local lsp_diagnostic = first.user_data and first.user_data.lsp or nil
local params = {
  textDocument = { uri = vim.uri_from_bufnr(buf) },
  range = {
    start = { line = first.lnum, character = first.col },
    ['end'] = { line = first.end_lnum, character = first.end_col },
  },
  context = { diagnostics = lsp_diagnostic and { lsp_diagnostic } or {} },
}
local responses = vim.lsp.buf_request_sync(buf, 'textDocument/codeAction', params, 20000)
if not responses then fail('no code action response') end
local applied = false
for _, response in pairs(responses) do
  for _, action in ipairs(response.result or {}) do
    if action.kind == 'quickfix' and not applied then
      vim.lsp.util.apply_workspace_edit(action.edit, 'utf-16')
      applied = true
    end
  end
end
if not applied then fail('no quick fix offered') end
local lines = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
local out = io.open(path .. '.result', 'w')
out:write(table.concat(lines, '\n') .. '\n')
out:write('DIAGNOSTICS ' .. #diagnostics .. ' FIRST ' .. tostring(first.code or (lsp_diagnostic and lsp_diagnostic.code)) .. '\n')
out:close()
vim.lsp.stop_client(client)
vim.cmd('qall!')
