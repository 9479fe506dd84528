"""``zero server``: zero in the editor, as a Language Server Protocol server over stdio.

Every answer comes from the engine (no rule is implemented twice): the findings are
``zero lint``'s with the file's project configuration, the formatting is ``zero format``,
the fixes are the findings' own. The modules below :mod:`zero.server.lsp` are plain
functions over an analysed document (:mod:`zero.server.documents`) that return
``lsprotocol`` values; only :mod:`zero.server.lsp` knows pygls. The command line starts
it (:func:`zero.server.lsp.serve`) and passes the registries in.
"""
