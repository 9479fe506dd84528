"""The protocol: a pygls language server with zero's features, over standard input and output.

Documents are synchronised incrementally; a document is linted when it is opened, and again
after a quiet spell once it changes (``debounce``, 250 ms by default), on the event loop's one
thread (the engine is never run twice at once). Lints nobody waits for (documents opened, a
machine's other lists after an edit, every open document after a save) wait in one queue, each
document once, and run one per turn of the event loop: requests are answered in between, and a
newer lint of a document (or its closing) drops its queued one. A request about a document whose findings are
not current lints it first, so that answers always match the text. Once an edited list of a
machine is linted, the other open documents of that machine (its lists, NC programs checked
against it) are linted again right after it: their X findings follow its unsaved text; a list
closed unsaved does the same. Saving any file, or a configuration file changing, reads the
projects' configuration and machines again and re-lints every open document. At most
``maxFindings`` findings (2000 by default) are published per document, then one saying how many
more ``zero lint`` reports. A client that pulls findings (``textDocument/diagnostic``) and can be
asked to pull again (``workspace/diagnostic/refresh``) gets them pulled and none pushed.

Nothing stops the server but ``exit``: a request whose parameters cannot be read is answered
with ``InvalidParams`` and said in one line on stderr (no traceback); a document that cannot be
read (a FIFO, a missing file named by a request) with ``RequestFailed`` and its reason; an error
inside zero with ``InternalError`` for a request, and for a document's findings as one diagnostic
saying so.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import logging
import os
import re
import sys
import threading
import time
import traceback
from collections import OrderedDict
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any
from urllib.parse import unquote

from lsprotocol import types
from pygls.exceptions import JsonRpcException, JsonRpcInvalidParams, JsonRpcInvalidRequest
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol
from pygls.workspace import TextDocument

from zero import __version__
from zero.engine.commands import Registries
from zero.errors import ZeroError
from zero.files import read_file
from zero.forms import CONFIG_NAMES
from zero.lists.encoding import decode
from zero.output.formats import rule_docs_template
from zero.server import actions, completion, findings, hover, outline
from zero.server.documents import Analysis, Projects
from zero.server.positions import path_of
from zero.server.settings import Settings

REQUEST_FAILED = -32803  # LSP ErrorCodes.RequestFailed
INVALID_PARAMS = -32602
WATCHED = "**/{" + ",".join(CONFIG_NAMES) + "}"  # the configuration files, as the resolver finds them
logger = logging.getLogger("zero.server")


class _Answered:
    """A request that was answered while it was read (its parameters could not be read)."""


ANSWERED = _Answered()


heard = [0.0]  # when the client's last message came (time.monotonic)
QUIET = 0.05  # seconds without a message before a queued lint runs: a request never waits behind the queue


class ZeroProtocol(LanguageServerProtocol):
    """pygls's protocol, answering a request whose parameters it cannot read with ``InvalidParams``
    (pygls would log it and leave the client waiting)."""

    def structure_message(self, data: dict[str, Any]) -> Any:
        try:
            return super().structure_message(data)  # its traceback dropped (_QuietRefusals): said here in a line
        except JsonRpcException as exc:
            if isinstance(data, dict) and "method" in data:
                why = f"{data.get('method')}: the parameters cannot be read: {_unreadable(exc)}"
                if "id" in data:
                    logger.warning("request %s refused: %s", _shown_id(data["id"]), why)
                    self._send_response(data["id"], error=JsonRpcInvalidParams(why).to_response_error())
                else:
                    logger.warning("notification ignored: %s", why)
                return ANSWERED
            logger.warning("a message from the client cannot be read: %s", _unreadable(exc))
            raise

    def handle_message(self, message: Any) -> None:
        heard[0] = time.monotonic()  # the queue of lints waits while the client is talking
        if message is ANSWERED:
            return
        if self._shutdown and getattr(message, "id", None) is not None \
                and getattr(message, "method", types.EXIT) != types.EXIT:  # a request, not a response
            error = JsonRpcInvalidRequest(f"{message.method}: the server is shutting down (shutdown was requested)")
            self._send_response(message.id, error=error.to_response_error())  # pygls would leave it unanswered
            return
        super().handle_message(message)


def _unreadable(exc: JsonRpcException) -> str:
    """What is wrong with a message's parameters, in one line (``$.params.position.line: invalid
    literal for int() with base 10: 'x'``), from the exception group cattrs raises."""
    cause = exc.__cause__
    said = "; ".join(_leaves(cause, "$")) if cause is not None else ""
    return (said or exc.message or type(exc).__name__)[:500]


_ATTRIBUTE = re.compile(r"@ (?:attribute|index|key) (.+)$")


def _leaves(exc: BaseException, path: str) -> list[str]:
    subs = getattr(exc, "exceptions", None)
    if not subs:
        text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        return [f"{path}: {text}"]
    out = []
    for sub in subs:
        where = next((m.group(1) for note in getattr(sub, "__notes__", []) if isinstance(note, str)
                      and (m := _ATTRIBUTE.search(note))), None)
        out.extend(_leaves(sub, f"{path}.{where}" if where is not None else path))
    return out


def _shown_id(msg_id: Any) -> str:
    return json.dumps(msg_id)[:80] if isinstance(msg_id, (str, int)) else "?"


def failed(message: str) -> JsonRpcException:
    return JsonRpcException(message, code=REQUEST_FAILED)


def expected(error: BaseException | None) -> bool:
    """A refusal zero answers on purpose (``RequestFailed``), not a fault of the server."""
    return isinstance(error, JsonRpcException) and error.code == REQUEST_FAILED


def refused(error: BaseException | None) -> bool:
    """A request refused for its parameters (``InvalidParams``): the client's fault, said in one line."""
    return isinstance(error, JsonRpcException) and error.code == INVALID_PARAMS


class _QuietRefusals(logging.Filter):
    """pygls logs every error answer with its traceback, and every message it cannot read with the
    traceback of its reading (40 lines at ERROR for a request with a bad position). A refusal is no
    error of the server: dropped here, and said in one line where it is answered
    (:meth:`ZeroProtocol.structure_message`, :meth:`ZeroServer.report_server_error`)."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.exc_info is not None and (expected(record.exc_info[1]) or refused(record.exc_info[1])):
            return False
        return not (record.name.startswith("pygls") and isinstance(record.msg, str)
                    and record.msg.startswith("Unable to deserialize message"))


class _Buffers(Mapping[str, str]):
    """The open documents' text by real path, looked up when asked (built for every analysis, the
    map cost a real path per open document: 5,000 open lists made each lint resolve 5,000 paths)."""

    def __init__(self, server: ZeroServer) -> None:
        self.server = server

    def __getitem__(self, real: str) -> str:
        doc = self.server.document(self.server.by_real[real])
        if doc is None:
            raise KeyError(real)
        return doc.source

    def __iter__(self) -> Iterator[str]:
        return iter(list(self.server.by_real))

    def __len__(self) -> int:
        return len(self.server.by_real)


class ZeroServer(LanguageServer):
    def __init__(self, registries: Registries, param_desc: Path | None = None) -> None:
        super().__init__("zero", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
                         protocol_cls=ZeroProtocol)
        self.settings = Settings()
        self.projects = Projects(registries, param_desc, self.settings)
        self.rule_docs = findings.RuleDocs(rule_docs_template())
        self.analyses: dict[str, Analysis] = {}
        self.timers: dict[str, asyncio.TimerHandle] = {}
        self.edited: set[str] = set()  # documents changed since they were last linted by their timer
        # Lints nobody waits for (documents opened, a machine's other lists after an edit, every open
        # document after a save): one per turn of the event loop, so that requests are answered in
        # between; each document once however often it is asked for, and not at all once a newer
        # lint of it (its own timer, a request) or its closing supersedes it.
        self.queue: OrderedDict[str, str] = OrderedDict()
        self.draining = False
        self.by_real: dict[str, str] = {}  # an open document's real path → its URI
        self.real_of: dict[str, str] = {}  # an open document (by decoded URI) → its real path
        self.pull = False  # the client pulls findings (textDocument/diagnostic): none pushed
        self.refresh = False  # … and may be told to pull again (workspace/diagnostic/refresh)
        self.snippets = False
        self.lazy_actions = False
        self.shut_down = False  # the client asked to shut down (exit then ends the process with 0, else 1)

    def report_server_error(self, error: Exception, source: Any) -> None:
        """Errors outside a request go to the client's log, not into pop-ups. A request zero refuses
        on purpose (``RequestFailed``: a list `zero format` cannot read) is answered with its reason
        and is no error of the server: not logged."""
        if expected(error):
            return
        if refused(error):
            message = error.message if isinstance(error, JsonRpcException) else str(error)
            logger.warning("request refused: %s", message.splitlines()[0] if message else type(error).__name__)
            return
        logger.error("%s", error)
        with contextlib.suppress(Exception):  # the client is gone: nothing to tell
            self.window_log_message(types.LogMessageParams(types.MessageType.Error, f"zero server: {error}"))

    # ------------------------------------------------------------------ documents

    @property
    def encoding(self) -> str:
        return str(getattr(self.workspace.position_encoding, "value", self.workspace.position_encoding) or "utf-16")

    def document(self, uri: str) -> TextDocument | None:
        """The open document of ``uri`` however the client percent-encodes it (pygls keeps them by the
        decoded URI: ``file:///c%3A/My%20Lists/x.lis`` is open as ``file:///c:/My Lists/x.lis``)."""
        doc: TextDocument | None = self.workspace.text_documents.get(unquote(uri))
        return doc

    def buffers(self) -> Mapping[str, str]:
        """The open documents' text by real path (for the machine's lists)."""
        return _Buffers(self)

    def opened(self, uri: str) -> None:
        """Where an open document lies (its real path, resolved once while it is open)."""
        path = path_of(uri)
        if path is not None:
            real = os.path.realpath(path)
            self.real_of[unquote(uri)] = real
            self.by_real[real] = uri

    def closed(self, uri: str) -> None:
        real = self.real_of.pop(unquote(uri), None)
        if real is not None and self.by_real.get(real) == uri:
            del self.by_real[real]
        self.queue.pop(unquote(uri), None)

    def enqueue(self, uri: str) -> None:
        """Lint a document soon, in the background (see ``queue``); nothing to do where its own timer
        is set already."""
        key = unquote(uri)
        if key in self.timers or key in self.queue:
            return
        self.queue[key] = uri
        if not self.draining:
            self.draining = True
            asyncio.get_running_loop().call_soon(self._drain)

    def _drain(self) -> None:
        self.draining = False
        if not self.queue or self.shut_down:
            return
        wait = heard[0] + QUIET - time.monotonic()
        if wait > 0:  # the client is talking (a thousand documents opened, a request): answer it first
            self.draining = True
            asyncio.get_running_loop().call_later(wait, self._drain)
            return
        _, uri = self.queue.popitem(last=False)
        try:
            self.publish(uri)
        finally:
            if self.queue and not self.draining:
                self.draining = True
                asyncio.get_running_loop().call_soon(self._drain)

    def analysis(self, uri: str) -> Analysis:
        """The current analysis of a document (linted now when it is not current); a document that is
        not open is read from its file (:class:`JsonRpcException` when it cannot be read)."""
        doc = self.document(uri)
        if doc is None:
            path = path_of(uri)
            if path is None:
                raise failed(f"{uri}: not open, and not a file")
            try:
                text = decode(read_file(path))[0]
            except ZeroError as exc:
                raise failed(str(exc)) from None
            return self.projects.analyse(uri, None, text, self.encoding, self.buffers())
        key = unquote(uri)
        hit = self.analyses.get(key)
        if hit is not None and hit.version == doc.version and hit.text.source == doc.source:
            return hit
        a = self.projects.analyse(doc.uri, doc.version, doc.source, self.encoding, self.buffers())
        self.analyses[key] = a
        return a

    def found(self, uri: str) -> list[types.Diagnostic]:
        """The findings of a document as published or pulled (at most ``maxFindings`` and one saying
        how many more; an error inside zero is said as one)."""
        try:
            a = self.analysis(uri)
            return findings.diagnostics(a, self.rule_docs, self.settings.max_findings)
        except JsonRpcException:
            raise
        except Exception as exc:  # a fault in zero: said on the document, never the end of the server
            logger.error("zero could not check %s:\n%s", uri, traceback.format_exc())
            return [types.Diagnostic(types.Range(types.Position(0, 0), types.Position(0, 0)),
                                     f"zero could not check this file (an error in zero, please report it): "
                                     f"{type(exc).__name__}: {exc}", severity=types.DiagnosticSeverity.Error,
                                     source="zero")]

    def publish(self, uri: str) -> None:
        """Lint a document and publish its findings; where it was edited, the other open documents of
        its machine are linted again next (their X findings follow its unsaved text)."""
        key = unquote(uri)
        self.timers.pop(key, None)
        self.queue.pop(key, None)  # this lint supersedes a queued one
        doc = self.document(uri)
        if doc is None:
            return
        before = self.analyses.get(key)
        if self.pull:
            with contextlib.suppress(Exception):  # said when the client pulls them
                self.analysis(uri)
        else:
            found = self.found(uri)
            self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(doc.uri, found,
                                                                                  version=doc.version))
        if key in self.edited:
            self.edited.discard(key)
            self.relint_machine(uri, before, self.analyses.get(key))

    def neighbours(self, uri: str, *analyses: Analysis | None) -> list[str]:
        """The other open documents on the machine of ``uri`` (as saved, and as ``analyses`` read it:
        an unsaved start-up list may name other lists): its lists, and NC programs checked against it."""
        lists: set[str] = set()
        startups: set[str] = set()
        machines = [a.machine for a in analyses if a is not None and a.machine is not None]
        path = path_of(uri)
        if path is not None:
            with contextlib.suppress(Exception):  # a machine that cannot be read: as the analyses read it
                saved = self.projects.machine(path)
                if saved is not None:
                    machines.append(saved)
        for m in machines:
            startups.add(os.path.realpath(m.startup.path))
            lists.update(os.path.realpath(lf.path) for lf in m.lists)
        lists |= startups
        me = os.path.realpath(path) if path is not None else None
        if me is None or me not in lists:
            return []  # not a list of a machine (an NC program, a list of none): nothing depends on its text
        out = []
        for doc in self.workspace.text_documents.values():
            real = self.real_of.get(unquote(doc.uri))
            if real is None or real == me:
                continue
            a = self.analyses.get(unquote(doc.uri))
            if real in lists or (a is not None and a.machine is not None
                                 and os.path.realpath(a.machine.startup.path) in startups):
                out.append(doc.uri)
        return out

    def relint_machine(self, uri: str, *analyses: Analysis | None) -> None:
        """Lint the other open documents of the machine again (pushed a moment later, each after the
        other; a client that pulls is asked to pull again)."""
        others = self.neighbours(uri, *analyses)
        for other in others:
            self.analyses.pop(unquote(other), None)
            if not self.pull:
                self.enqueue(other)
        if others and self.pull and self.refresh:
            future = self.workspace_diagnostic_refresh(None)
            future.add_done_callback(lambda f: f.cancelled() or f.exception())

    def schedule(self, uri: str, delay: float | None = None) -> None:
        self.cancel(uri)
        # never below MIN_DEBOUNCE: changes already waiting in the stream (a client that types faster
        # than zero lints, or one that is gone) supersede each other instead of each being linted
        wait = max(self.settings.debounce, MIN_DEBOUNCE) if delay is None else delay
        self.timers[unquote(uri)] = asyncio.get_running_loop().call_later(wait, self.publish, uri)

    def cancel(self, uri: str) -> None:
        """The pending lint of a document, if any, is not run."""
        old = self.timers.pop(unquote(uri), None)
        if old is not None:
            old.cancel()

    def refresh_all(self) -> None:
        """Configuration or lists on disk changed: read them again and re-lint every open document."""
        self.projects.forget()
        self.analyses.clear()
        self.by_real.clear()
        self.real_of.clear()
        for doc in list(self.workspace.text_documents.values()):  # links may have changed: resolved again
            self.opened(doc.uri)
            self.enqueue(doc.uri)


def create_server(registries: Registries, param_desc: Path | None = None) -> ZeroServer:
    """The language server with every feature registered (``registries`` as the command line has them)."""
    server = ZeroServer(registries, param_desc)

    @server.feature(types.INITIALIZE)
    def initialize(params: types.InitializeParams) -> None:
        refused = server.settings.update(params.initialization_options)
        server.rule_docs = findings.RuleDocs(server.settings.rule_docs or rule_docs_template())
        caps = params.capabilities.text_document
        item = caps.completion.completion_item if caps and caps.completion else None
        server.snippets = bool(item and item.snippet_support)
        resolve = caps.code_action.resolve_support if caps and caps.code_action else None
        server.lazy_actions = bool(resolve and "edit" in resolve.properties)
        workspace = params.capabilities.workspace
        server.refresh = bool(workspace and workspace.diagnostics and workspace.diagnostics.refresh_support)
        # pull where the client pulls and can be told to pull again (a neighbour's edit changes the
        # findings of a list it does not touch): else pushed, and no diagnosticProvider advertised
        if caps is not None and caps.diagnostic is not None and server.refresh and not server.pull:
            server.pull = True
            server.feature(types.TEXT_DOCUMENT_DIAGNOSTIC, types.DiagnosticOptions(
                inter_file_dependencies=True, workspace_diagnostics=False, identifier="zero"))(on_diagnostic)
        if refused:
            logger.warning("unknown or bad settings ignored: %s", ", ".join(refused))

    @server.feature(types.INITIALIZED)
    def initialized(params: types.InitializedParams) -> None:
        watch = server.client_capabilities.workspace
        dynamic = watch.did_change_watched_files if watch else None
        if dynamic is not None and dynamic.dynamic_registration:
            options = types.DidChangeWatchedFilesRegistrationOptions([types.FileSystemWatcher(WATCHED)])
            future = server.client_register_capability(types.RegistrationParams(
                [types.Registration("zero-config", types.WORKSPACE_DID_CHANGE_WATCHED_FILES, options)]))
            future.add_done_callback(lambda f: f.cancelled() or f.exception())  # a refusal is no error

    @server.feature(types.SHUTDOWN)
    def shutdown(params: None) -> None:
        server.shut_down = True
        server.queue.clear()
        for uri in list(server.timers):
            server.cancel(uri)

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(params: types.DidOpenTextDocumentParams) -> None:
        uri = params.text_document.uri
        if len(server.workspace.text_documents) <= 1:  # a configuration file may have changed while nothing
            server.projects.forget()  # was open (while others are, a change is watched or saved: refresh_all)
        server.opened(uri)
        server.enqueue(uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(params: types.DidChangeTextDocumentParams) -> None:
        server.edited.add(unquote(params.text_document.uri))
        server.schedule(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(params: types.DidSaveTextDocumentParams) -> None:
        server.refresh_all()

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(params: types.DidCloseTextDocumentParams) -> None:
        uri = params.text_document.uri
        server.cancel(uri)
        server.closed(uri)
        server.edited.discard(unquote(uri))
        closed = server.analyses.pop(unquote(uri), None)
        if closed is not None and not closed.saved:  # its unsaved text no longer counts for the machine
            server.relint_machine(uri, closed)
        if not server.pull:
            server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri, []))

    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def watched(params: types.DidChangeWatchedFilesParams) -> None:
        server.refresh_all()

    @server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
    def configuration(params: types.DidChangeConfigurationParams) -> None:
        server.settings.update(params.settings)
        server.rule_docs = findings.RuleDocs(server.settings.rule_docs or rule_docs_template())
        server.refresh_all()

    def on_diagnostic(params: types.DocumentDiagnosticParams) -> types.RelatedFullDocumentDiagnosticReport:
        return types.RelatedFullDocumentDiagnosticReport(items=server.found(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_LINK)
    def on_document_link(params: types.DocumentLinkParams) -> list[types.DocumentLink]:
        return outline.document_links(server.analysis(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    def on_folding_range(params: types.FoldingRangeParams) -> list[types.FoldingRange]:
        return outline.folding_ranges(server.analysis(params.text_document.uri))

    @server.command(actions.FIX_ALL_COMMAND)
    async def fix_all(*args: Any) -> dict[str, Any]:
        uri = actions.uri_argument(actions.FIX_ALL_COMMAND, args, 1)
        a = server.analysis(uri)
        edit = actions.fix_all_edit(a)
        if edit is None or not edit.changes:
            return {"applied": True, "edits": 0}
        count = sum(len(e) for e in edit.changes.values())
        answer = await server.workspace_apply_edit_async(types.ApplyWorkspaceEditParams(
            edit, label="zero: fix all (zero lint --fix)"))
        return {"applied": bool(answer.applied), "edits": count,
                **({"reason": answer.failure_reason} if answer.failure_reason else {})}

    @server.command(actions.SHOW_EFFECTIVE_VALUE)
    def show_effective_value(*args: Any) -> dict[str, Any]:
        uri = actions.uri_argument(actions.SHOW_EFFECTIVE_VALUE, args, 2)
        line, character = actions.position_argument(actions.SHOW_EFFECTIVE_VALUE, args[1])
        shown = actions.effective_value(server.analysis(uri), line, character)
        server.window_show_message(types.ShowMessageParams(types.MessageType.Info, shown["message"]))
        return shown

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    def on_hover(params: types.HoverParams) -> types.Hover | None:
        a = server.analysis(params.text_document.uri)
        return hover.hover(a, params.position.line, params.position.character)

    @server.feature(types.TEXT_DOCUMENT_COMPLETION,
                    types.CompletionOptions(trigger_characters=completion.TRIGGERS, resolve_provider=True))
    def on_completion(params: types.CompletionParams) -> types.CompletionList:
        a = server.analysis(params.text_document.uri)
        found = completion.completion(a, params.position.line, params.position.character, server.snippets)
        for item in found.items:
            if isinstance(item.data, dict):
                item.data["uri"] = a.uri  # resolved with the registry of the document's project
        return found

    @server.feature(types.COMPLETION_ITEM_RESOLVE)
    def on_completion_resolve(item: types.CompletionItem) -> types.CompletionItem:
        uri = item.data.get("uri") if isinstance(item.data, dict) else None
        registry = server.analysis(uri).registry if isinstance(uri, str) else \
            server.projects.registries(server.projects.project.param_desc_given)
        return completion.resolve(item, registry)

    @server.feature(types.TEXT_DOCUMENT_SIGNATURE_HELP,
                    types.SignatureHelpOptions(trigger_characters=["[", " ", "="], retrigger_characters=[","]))
    def on_signature_help(params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        a = server.analysis(params.text_document.uri)
        return completion.signature_help(a, params.position.line, params.position.character)

    @server.feature(types.TEXT_DOCUMENT_CODE_ACTION,
                    types.CodeActionOptions(code_action_kinds=actions.KINDS, resolve_provider=True))
    def on_code_action(params: types.CodeActionParams) -> list[types.CodeAction]:
        a = server.analysis(params.text_document.uri)
        return actions.code_actions(a, params.range, params.context.only, server.rule_docs, server.lazy_actions)

    @server.feature(types.CODE_ACTION_RESOLVE)
    def on_code_action_resolve(action: types.CodeAction) -> types.CodeAction:
        data = action.data if isinstance(action.data, dict) else {}
        uri = data.get("uri")
        if not isinstance(uri, str):
            return action
        return actions.resolve(server.analysis(uri), action)

    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    def on_formatting(params: types.DocumentFormattingParams) -> list[types.TextEdit]:
        a = server.analysis(params.text_document.uri)
        try:
            return actions.formatting(a)
        except ZeroError as exc:
            raise failed(f"zero format: {exc} (not formatted)") from None

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    def on_range_formatting(params: types.DocumentRangeFormattingParams) -> list[types.TextEdit]:
        a = server.analysis(params.text_document.uri)
        try:
            return actions.range_formatting(a, params.range)
        except ZeroError as exc:
            raise failed(f"zero format: {exc} (not formatted)") from None

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def on_symbols(params: types.DocumentSymbolParams) -> list[types.DocumentSymbol]:
        return outline.document_symbols(server.analysis(params.text_document.uri))

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    def on_definition(params: types.DefinitionParams) -> list[types.Location]:
        a = server.analysis(params.text_document.uri)
        return outline.definition(a, params.position.line, params.position.character)

    return server


MIN_DEBOUNCE = 0.02  # seconds
MAX_MESSAGE_BYTES = 64 * 1024 * 1024  # one message from the client (a 30 MB list opened is 60 MB of JSON)
MAX_HEADER_BYTES = 8192
_CONTENT_LENGTH = re.compile(rb"content-length[ \t]*:[ \t]*([0-9]{1,12})[ \t]*", re.IGNORECASE)
_HEADER_START = re.compile(rb"content-length[ \t]*:", re.IGNORECASE)
_SWALLOWED = re.compile(rb"\}[ \t\r\n]*content-length[ \t]*:[ \t]*[0-9]+[ \t]*\r\n", re.IGNORECASE)  # a next message


def _whole_json(body: bytes) -> bool:
    """Is the body one JSON object? Parsed where small; a large one (a list opened) is checked by
    its shape only, so that pygls's parse is the only one: an object, and no header inside it."""
    if len(body) <= 1 << 20:
        try:
            return isinstance(json.loads(body.decode("utf-8", "surrogateescape")), dict)
        except (ValueError, RecursionError):
            return False
    text = body.strip()
    return text.startswith(b"{") and text.endswith(b"}") and _SWALLOWED.search(text) is None


class FramedInput:
    """The client's stream as pygls reads it, each message checked before pygls sees it.

    pygls trusts the framing: a ``Content-Length`` that is not a number, missing, or wrong made it
    read the next message's header as a body (or wait for bytes that never come), and the server
    never answered again, not even ``shutdown``. Here each message is read whole, its header and
    its JSON checked; a broken one is answered with a JSON-RPC parse error (id ``null``), said on
    stderr, and reading goes on at the next ``Content-Length`` header. pygls gets only well-formed
    messages, re-framed. A message over ``MAX_MESSAGE_BYTES`` is skipped without being held.

    JSON-RPC is UTF-8, but an editor may send a buffer it could not decode (Neovim does, for a
    Latin-1 file read as UTF-8): a byte that is not UTF-8 reaches zero as the lone surrogate zero
    keeps such bytes as (``surrogateescape``), and is reported where it is (S007)."""

    def __init__(self, stream: Any, reply: Callable[[bytes], None] | None = None) -> None:
        self.stream = stream
        self.reply = reply
        self._raw = bytearray()  # read from the client, not yet framed
        self._out = bytearray()  # framed for pygls, not yet read by it
        self._eof = False

    # pygls's side
    def readline(self) -> bytes:
        if not self._out and not self._next():
            return b""
        end = self._out.find(b"\n")
        cut = len(self._out) if end < 0 else end + 1
        line = bytes(self._out[:cut])
        del self._out[:cut]
        return line

    def read(self, size: int = -1) -> bytes:
        if not self._out and not self._next():
            return b""
        cut = len(self._out) if size < 0 else min(size, len(self._out))
        data = bytes(self._out[:cut])
        del self._out[:cut]
        return data

    # the client's side
    def _fill(self) -> bool:
        if self._eof:
            return False
        read1 = getattr(self.stream, "read1", None)
        chunk = read1(65536) if read1 is not None else self.stream.read(65536)
        if not chunk:
            self._eof = True
            return False
        self._raw += chunk
        return True

    def _refuse(self, why: str) -> None:
        logger.warning("a message from the client is not valid, skipped: %s", why)
        if self.reply is not None:
            body = json.dumps({"jsonrpc": "2.0", "id": None, "error": {"code": -32700, "message": why}}).encode()
            with contextlib.suppress(OSError, ValueError):
                self.reply(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def _resync(self, start: int, after: int | None = None) -> None:
        """Drop what cannot be a message, up to the next ``Content-Length`` header: right ``after`` a
        body whose length was right but whose content was not, else the first one from ``start``."""
        if after is not None:
            while len(self._raw) < after + 16 and self._fill():
                pass
            if _HEADER_START.match(self._raw, after):
                del self._raw[:after]
                return
        m = _HEADER_START.search(self._raw, start)
        if m is None:  # keep what may be the start of a header cut in two by the read, and no more:
            last = self._raw.rfind(b"\r\n\r\n")  # never a header's end seen already (it looped on it)
            del self._raw[: max(start, len(self._raw) - 15, last + 4 if last >= 0 else 0)]
            return
        del self._raw[:m.start()]

    def _next(self) -> bool:
        """Frame the next valid message into the output; ``False`` at the end of the stream."""
        while True:
            end = self._raw.find(b"\r\n\r\n")
            if end < 0:
                if len(self._raw) > MAX_HEADER_BYTES:
                    self._refuse("no end of the header within 8192 bytes")
                    self._resync(1)
                    continue
                if not self._fill():
                    return False
                continue
            header = bytes(self._raw[:end])
            m = None
            for line in header.split(b"\r\n"):
                m = _CONTENT_LENGTH.fullmatch(line) or m
            if m is None:
                self._refuse("a header without a valid Content-Length")
                self._resync(1)
                continue
            length = int(m.group(1))
            start = end + 4
            if length > MAX_MESSAGE_BYTES:
                self._refuse(f"a message of {length} bytes, over the {MAX_MESSAGE_BYTES} the server reads")
                self._skip(start)
                continue
            while len(self._raw) < start + length:
                if not self._fill():
                    return False
            body = bytes(self._raw[start:start + length])
            if not _whole_json(body):
                self._refuse("a body that is not JSON (is its Content-Length right?)")
                self._resync(start, start + length)
                continue
            del self._raw[:start + length]
            try:
                body.decode("utf-8")
            except UnicodeDecodeError:
                body = body.decode("utf-8", "surrogateescape").encode("utf-8", "surrogatepass")
            self._out += b"Content-Length: %d\r\n\r\n" % len(body) + body
            return True

    def _skip(self, start: int) -> None:
        """Read past a message too large to hold, keeping nothing of it: up to the next header that
        follows the end of a JSON object (its length is not trusted: it may be any number)."""
        del self._raw[:start]
        while True:
            m = _SWALLOWED.search(self._raw)
            if m is not None:
                del self._raw[:m.start() + 1]
                return
            del self._raw[: max(0, len(self._raw) - 64)]  # a header may be cut in two by the read
            if not self._fill():
                self._raw.clear()
                return


def serve(registries: Registries, param_desc: Path | None = None) -> None:
    """Run the server over standard input and output until the client says ``exit`` (exit code 0 after
    ``shutdown``, else 1)."""
    stdout = sys.stdout.buffer
    sys.stdout = sys.stderr  # nothing but the protocol may reach the client's stream
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter("zero server: %(levelname)s %(name)s: %(message)s"))
    handler.addFilter(_QuietRefusals())
    root = logging.getLogger()
    root.addHandler(handler)
    root.setLevel(logging.WARNING)
    server = create_server(registries, param_desc)
    lock = threading.Lock()

    def reply(data: bytes) -> None:  # a parse error, written whole beside pygls's messages
        with lock:
            stdout.write(data)
            stdout.flush()

    server.start_io(FramedInput(sys.stdin.buffer, reply), stdout)  # type: ignore[arg-type]
    if not server.shut_down:  # `exit` without `shutdown`, or the client gone: 1, as the protocol says
        raise SystemExit(1)
