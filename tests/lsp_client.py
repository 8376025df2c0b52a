"""A Language Server Protocol client of our own, over a server process's standard pipes.

It speaks JSON-RPC as an editor does: ``Content-Length`` framed messages,
requests answered by id, notifications (``publishDiagnostics``) gathered as
they come.  It shares no code with the server (which is pygls), so a test
sees what an editor would.
"""
from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
import time
from pathlib import Path

TIMEOUT = 30.0     # seconds for one answer (a loaded CI machine is slow to start Python)


class LspClient:
    def __init__(self, command=(sys.executable, "-m", "rapidmc", "lsp")):
        self.process = subprocess.Popen(list(command), stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.messages: "queue.Queue[dict]" = queue.Queue()
        self.notifications: list[dict] = []
        self.read_up_to = 0           # notifications ``diagnostics`` has looked at
        self.next_id = 0
        threading.Thread(target=self._read, daemon=True).start()

    # --- framing ------------------------------------------------------------------

    def _send(self, message: dict) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def _read(self) -> None:
        stream = self.process.stdout
        while True:
            length = None
            while True:
                header = stream.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                name, _, value = header.decode("ascii").partition(":")
                if name.strip().lower() == "content-length":
                    length = int(value)
            self.messages.put(json.loads(stream.read(length)))

    def _next(self, deadline: float) -> dict:
        while True:
            try:
                message = self.messages.get(timeout=0.2)
                break
            except queue.Empty:
                if self.process.poll() is not None or time.monotonic() > deadline:
                    raise AssertionError("the server did not answer; stderr: "
                                         + self._stderr()) from None
        if "id" not in message:
            self.notifications.append(message)
        return message

    def _stderr(self) -> str:
        if self.process.poll() is None:
            return "(still running)"
        return self.process.stderr.read().decode("utf-8", "replace")

    # --- messages -----------------------------------------------------------------

    def request(self, method: str, params: dict):
        self.next_id += 1
        number = self.next_id
        self._send({"id": number, "method": method, "params": params})
        deadline = time.monotonic() + TIMEOUT
        while True:
            message = self._next(deadline)
            if message.get("id") == number and "method" not in message:
                assert "error" not in message, message["error"]
                return message.get("result")

    def notify(self, method: str, params: dict) -> None:
        self._send({"method": method, "params": params})

    def diagnostics(self, uri: str) -> list[dict]:
        """The diagnostics of the next ``publishDiagnostics`` for ``uri`` (waiting for it):
        each call reads on from the one the previous call returned."""
        deadline = time.monotonic() + TIMEOUT
        while True:
            while self.read_up_to < len(self.notifications):
                message = self.notifications[self.read_up_to]
                self.read_up_to += 1
                if message.get("method") == "textDocument/publishDiagnostics" and \
                        message["params"]["uri"] == uri:
                    return message["params"]["diagnostics"]
            self._next(deadline)

    # --- a session ----------------------------------------------------------------

    def initialize(self, root: Path) -> dict:
        result = self.request("initialize", {"processId": None, "rootUri": root.as_uri(),
                                             "capabilities": {}})
        self.notify("initialized", {})
        return result

    def open(self, path: Path, text: str) -> None:
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": path.as_uri(), "languageId": "rapid", "version": 1, "text": text}})

    def change(self, path: Path, text: str, version: int = 2) -> None:
        self.notify("textDocument/didChange", {
            "textDocument": {"uri": path.as_uri(), "version": version},
            "contentChanges": [{"text": text}]})

    def at(self, method: str, path: Path, line: int, character: int):
        return self.request(method, {"textDocument": {"uri": path.as_uri()},
                                     "position": {"line": line, "character": character}})

    def close(self) -> int:
        """Shut the server down as an editor does; its exit code."""
        self.request("shutdown", None)
        self.notify("exit", None)
        try:
            return self.process.wait(timeout=TIMEOUT)
        finally:
            for stream in (self.process.stdin, self.process.stdout, self.process.stderr):
                stream.close()
