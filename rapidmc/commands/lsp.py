"""``rapidmc lsp``: a Language Server over standard input and output, for editors.

On every opened, changed or closed document it publishes the diagnostics of
each open document (``findings.editor``: syntax errors, else static errors
and lint findings); hover on a predefined routine shows its signature and
how rapidmc models it, hover on a declared name its declaration
(``report.hover``); go to definition finds the declaration of the name under
the cursor in the open modules (``findings.declarations``).  The server is
pygls (``pip install rapidmc[lsp]``); without it the command is a
diagnostic (RMC850) and exit 2.  It runs until the editor asks it to exit.
"""
from __future__ import annotations

import argparse
import sys

from ..diagnostics import EXIT_OK, LSP_UNAVAILABLE, error
from ..findings.declarations import declaration_at, word_at
from ..findings.editor import Workspace
from ..report.hover import declaration_hover, predefined_hover
from ..report.lsp_diagnostics import document_lines, lsp_diagnostic, lsp_location


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--stdio", action="store_true",
                        help="talk over standard input and output (the only transport; "
                        "accepted because editors pass it)")


def execute(args: argparse.Namespace) -> int:
    server = build_server()
    server.start_io(sys.stdin.buffer, sys.stdout.buffer)
    return EXIT_OK


def build_server():
    """The pygls server with rapidmc's features registered."""
    try:
        from lsprotocol import types
        from pygls.lsp.server import LanguageServer
    except ImportError:
        raise error(LSP_UNAVAILABLE, "'rapidmc lsp' needs pygls, which is not installed",
                    None, "install it with: pip install 'rapidmc[lsp]'") from None
    from .. import __version__
    server = LanguageServer("rapidmc", __version__,
                            text_document_sync_kind=types.TextDocumentSyncKind.Full)
    editor = _Editor(server, types)
    for method, answer in ((types.TEXT_DOCUMENT_DID_OPEN, editor.opened),
                           (types.TEXT_DOCUMENT_DID_CHANGE, editor.opened),
                           (types.TEXT_DOCUMENT_DID_CLOSE, editor.closed),
                           (types.TEXT_DOCUMENT_HOVER, editor.hover),
                           (types.TEXT_DOCUMENT_DEFINITION, editor.definition)):
        server.feature(method)(_handler(answer))
    return server


def _handler(answer):
    """A function for pygls to register (it marks what it registers: a bound method
    takes no marks)."""
    def handle(params):
        return answer(params)
    return handle


class _Editor:
    """The open documents (by file name) and the answers to the editor's requests."""

    def __init__(self, server, types):
        self.server = server
        self.types = types
        self.workspace = Workspace(read_folders=True)
        self.uris: dict[str, str] = {}      # file name in spans -> document URI
        from lsprotocol.converters import get_converter
        self.converter = get_converter()      # LSP JSON data -> lsprotocol types

    def _file(self, uri: str) -> str:
        from pygls.uris import to_fs_path
        file = (to_fs_path(uri) if uri.startswith("file:") else None) or uri
        self.uris[file] = uri
        return file

    def opened(self, params) -> None:
        uri = params.text_document.uri
        text = self.server.workspace.get_text_document(uri).source
        self.workspace.update(self._file(uri), text)
        self.publish()

    def closed(self, params) -> None:
        file = self._file(params.text_document.uri)
        self.workspace.remove(file)
        self._send(file, [])
        self.publish()

    def publish(self) -> None:
        """The diagnostics of every open document (a change in one may settle another's)."""
        for file in list(self.workspace.documents):
            lines = document_lines(self.workspace.text(file))
            self._send(file, [lsp_diagnostic(d, lines, self._uri)
                              for d in self.workspace.diagnostics(file)])

    def _send(self, file: str, diagnostics: list) -> None:
        self.server.text_document_publish_diagnostics(self.types.PublishDiagnosticsParams(
            uri=self.uris[file],
            diagnostics=[self.converter.structure(d, self.types.Diagnostic) for d in diagnostics]))

    def _word(self, params):
        """(file, line number, word) under the cursor, or None."""
        file = self._file(params.text_document.uri)
        text = self.workspace.text(file)
        line = params.position.line
        lines = document_lines(text) if text is not None else []
        if line >= len(lines):
            return None
        found = word_at(lines[line], params.position.character)
        return None if found is None else (file, line + 1, found[0])

    def _named(self, params):
        """(word under the cursor, the declaration it refers to or None), or None off a name."""
        place = self._word(params)
        if place is None:
            return None
        file, line, word = place
        return word, declaration_at(self.workspace.program_modules(file), file, line, word)

    def hover(self, params):
        named = self._named(params)
        if named is None:
            return None
        word, declaration = named
        text = declaration_hover(declaration) if declaration else predefined_hover(word)
        if text is None:
            return None
        return self.types.Hover(contents=self.types.MarkupContent(
            kind=self.types.MarkupKind.Markdown, value=text))

    def definition(self, params):
        named = self._named(params)
        if named is None or named[1] is None:
            return None
        name = named[1].name
        return self.converter.structure(lsp_location(self._uri(name.span.file), name.span,
                                                     len(name.text)),
                                        self.types.Location)

    def _uri(self, file: str) -> str:
        """The URI of an open document's file name, or of a file on disk."""
        from pygls.uris import from_fs_path
        return self.uris.get(file) or from_fs_path(file) or file
